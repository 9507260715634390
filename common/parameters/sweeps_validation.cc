// The checks of the sweeps that go beyond one entry's range (validate() in valve_validation.cc runs
// them in its order).
#include "common/error.h"
#include "common/parameters/sweeps.h"
#include "common/parameters/validation_helpers.h"
#include "common/units.h"
#include "common/valve_description.h"

#include <string>
#include <utility>

namespace servodrift
{
  using namespace validation;

  void SweepParameters::validate() const
  {
    require_increasing(table_temperatures, "Sweeps/Table temperatures");
    require_increasing(motor_angles, "Sweeps/Motor angles", units::degree);
    require_increasing(motor_currents, "Sweeps/Motor currents");
    require_increasing(pressure_fractions, "Sweeps/Pressure fractions");
    require_increasing(gap_fractions, "Sweeps/Gap fractions");
    require_increasing(field_orifice_pressure_fractions, "Sweeps/Field orifice pressure fractions");
    require_increasing(field_gap_fractions, "Sweeps/Field gap fractions");
    require_increasing(field_nozzle_pressure_fractions, "Sweeps/Field nozzle pressure fractions");
    for (const auto &[list, entry] :
         {std::make_pair(&field_orifice_pressure_fractions, "Sweeps/Field orifice pressure fractions"),
          std::make_pair(&field_gap_fractions, "Sweeps/Field gap fractions"),
          std::make_pair(&field_nozzle_pressure_fractions, "Sweeps/Field nozzle pressure fractions")})
      if (!(list->front() > 0))
        refuse(entry, "starts with " + format_number(list->front()) +
                        ": the field level computes only flowing cases (> 0; the table adds the zero row itself)");
    require_increasing(drift_temperatures, "Sweeps/Drift temperatures");
    require_increasing(deviation_angles, "Sweeps/Deviation angles", units::degree);
  }

  void SweepParameters::validate(const ValveDescription &v) const
  {
    // The drift temperatures and the reference temperature within the table temperatures: a
    // coefficient table is not extrapolated
    const auto &op = v.operating;
    const double T_lo = table_temperatures.front(), T_hi = table_temperatures.back();
    auto check_in_tables = [&](double T, const std::string &entry) {
      if (!(T >= T_lo && T <= T_hi))
        refuse(entry, "contains " + format_number(T) + " degC, outside the table temperatures [" +
                        format_number(T_lo) + ", " + format_number(T_hi) + "] degC (`Sweeps/Table temperatures')");
    };
    for (double T : drift_temperatures)
      check_in_tables(T, "Sweeps/Drift temperatures");
    check_in_tables(op.reference_temperature, "Operating conditions/Reference temperature");
  }
} // namespace servodrift
