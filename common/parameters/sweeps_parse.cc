#include "common/parameters/sweeps.h"

#include "common/parameters/parameter_source.h"
#include "common/units.h"

namespace servodrift
{
  using namespace parameters;

  void SweepParameters::parse_parameters(ParameterSource &prm)
  {
    prm.enter_subsection(subsection);
    table_temperatures = prm.get_double_list("Table temperatures");
    motor_angles = prm.get_double_list("Motor angles");
    for (double &a : motor_angles)
      a *= units::degree;
    motor_currents = prm.get_double_list("Motor currents");
    pressure_fractions = prm.get_double_list("Pressure fractions");
    gap_fractions = prm.get_double_list("Gap fractions");
    field_orifice_pressure_fractions = prm.get_double_list("Field orifice pressure fractions");
    field_gap_fractions = prm.get_double_list("Field gap fractions");
    field_nozzle_pressure_fractions = prm.get_double_list("Field nozzle pressure fractions");
    drift_temperatures = prm.get_double_list("Drift temperatures");
    deviation_angles = prm.get_double_list("Deviation angles");
    for (double &a : deviation_angles)
      a *= units::degree;
    prm.leave_subsection();
  }
} // namespace servodrift
