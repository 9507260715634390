#include "common/parameters/thermal_expansion.h"

#include "common/parameters/parameter_helpers.h"

namespace servodrift
{
  using namespace parameters;

  void ThermalExpansion::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    const Patterns::Double alpha(-1e-3, 1e-3);
    prm.declare_entry("Spring tube", "17.8e-6", alpha,
                      "Expansion coefficient alpha_s of the spring tube, BeCu QBe2 / C17200 (E6, E7, "
                      "E13). [1/degC]");
    prm.declare_entry("Armature", "9.0e-6", alpha,
                      "Expansion coefficient alpha_ar of the armature, 1J50 (E6, E7). [1/degC]");
    prm.declare_entry("Pole pieces", "9.0e-6", alpha,
                      "Expansion coefficient alpha_c of the pole pieces (magnetic conductor), 1J50 "
                      "(E6, E7). [1/degC]");
    prm.declare_entry("Magnet", "11.0e-6", alpha,
                      "Expansion coefficient alpha_m of the magnets, AlNiCo 8 / LNGT60 (E7, E8). "
                      "[1/degC]");
    prm.declare_entry("Body", "10.8e-6", alpha,
                      "Expansion coefficient of the valve body that carries the nozzle seats, 17-4PH "
                      "(2.3; use about 23e-6 for an aluminium body). [1/degC]");
    prm.declare_entry("Nozzle", "10.8e-6", alpha,
                      "Expansion coefficient of the nozzles and fixed orifices, 17-4PH (2.3). [1/degC]");
    prm.declare_entry("Flapper", "10.8e-6", alpha,
                      "Expansion coefficient of the flapper, 17-4PH (2.3). [1/degC]");
    prm.declare_entry("Spool", "10.2e-6", alpha,
                      "Expansion coefficient of spool and sleeve, 440C / 9Cr18 (2.3). [1/degC]");
    prm.leave_subsection();
  }
} // namespace servodrift
