#include "common/parameters/spring_tube.h"

#include "common/parameters/parameter_helpers.h"

namespace servodrift
{
  using namespace parameters;

  void SpringTubeParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    prm.declare_entry("Model level", "reduced-order", Patterns::Selection("reduced-order"),
                      "Which model computes the spring_tube table: 'reduced-order' is the beam closed "
                      "form E11-E13 (D13). [-]");
    prm.declare_entry("Young's modulus", "128e9", Patterns::Double(0, 1e13),
                      "Young's modulus E_ref of the tube (BeCu QBe2) at the tube's reference "
                      "temperature (E12). [Pa]");
    prm.declare_entry("Reference temperature", "20", Patterns::Double(-273.15, 1000),
                      "Temperature at which E, D, d and l are given; E13 uses T - T_ref (C3). [degC]");
    prm.declare_entry("Modulus temperature coefficient", "3.5e-4", Patterns::Double(-0.01, 0.01),
                      "eta in E(T) = E_ref (1 - eta (T - T_ref)) (E12). RV-1: 3.5e-4 (D5, CDA Pub. 54); "
                      "the paper's literal eta = 0.04 alpha_s = 7.1e-7 only in the paper preset. "
                      "[1/degC]");
    prm.declare_entry("Poisson ratio", "0.30", Patterns::Double(0, 0.5),
                      "Poisson ratio of the tube material (field level). [1]");
    prm.declare_entry("Outer diameter", "3.60e-3", Patterns::Double(0, 1),
                      "Outer diameter D of the thin-walled section (E11). [m]");
    prm.declare_entry("Inner diameter", "3.40e-3", Patterns::Double(0, 1),
                      "Inner diameter d of the thin-walled section, below D (E11). [m]");
    prm.declare_entry("Length", "10.0e-3", Patterns::Double(0, 1),
                      "Length l of the thin-walled section (E11). [m]");
    prm.declare_entry("Yield strength", "1.0e9", Patterns::Double(0, 1e11),
                      "Yield strength of the age-hardened BeCu, for the stress margin. [Pa]");
    prm.leave_subsection();
  }

  void SpringTubeParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    model_level = prm.get("Model level");
    youngs_modulus = prm.get_double("Young's modulus");
    reference_temperature = prm.get_double("Reference temperature");
    modulus_temperature_coefficient = prm.get_double("Modulus temperature coefficient");
    poisson_ratio = prm.get_double("Poisson ratio");
    outer_diameter = prm.get_double("Outer diameter");
    inner_diameter = prm.get_double("Inner diameter");
    length = prm.get_double("Length");
    yield_strength = prm.get_double("Yield strength");
    prm.leave_subsection();
  }
} // namespace servodrift
