#include "common/parameters/fits.h"

#include "common/parameters/parameter_helpers.h"

namespace servodrift
{
  using namespace parameters;

  void FitParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    prm.declare_entry("Torque motor degrees", "2, 3, 2", integer_list(0, 8, 3, 3),
                      "Largest power of temperature, angle and current in the full polynomial fitted "
                      "to the torque_motor table's torque. [1]");
    prm.declare_entry("Spring tube degrees", "2", integer_list(0, 8, 1, 1),
                      "Largest power of temperature in the polynomial fitted to the spring_tube "
                      "table's stiffness. [1]");
    prm.declare_entry("Fixed orifice degrees", "2, 3", integer_list(0, 8, 2, 2),
                      "Largest power of temperature and pressure difference in the full polynomial "
                      "fitted to the fixed_orifice table's discharge coefficient. [1]");
    prm.declare_entry("Nozzle flapper degrees", "2, 3, 2", integer_list(0, 8, 3, 3),
                      "Largest power of temperature, gap and pressure difference in the full "
                      "polynomials fitted to the nozzle_flapper table's discharge coefficient and "
                      "flapper force. [1]");
    prm.leave_subsection();
  }
} // namespace servodrift
