#include "common/parameters/fits.h"

#include "common/parameters/parameter_source.h"

namespace servodrift
{
  using namespace parameters;

  void FitParameters::parse_parameters(ParameterSource &prm)
  {
    prm.enter_subsection(subsection);
    torque_motor_degrees = prm.get_integer_list("Torque motor degrees");
    spring_tube_degrees = prm.get_integer_list("Spring tube degrees");
    fixed_orifice_degrees = prm.get_integer_list("Fixed orifice degrees");
    nozzle_flapper_degrees = prm.get_integer_list("Nozzle flapper degrees");
    prm.leave_subsection();
  }
} // namespace servodrift
