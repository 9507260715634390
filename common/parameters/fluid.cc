#include "common/parameters/fluid.h"

#include "common/parameters/parameter_helpers.h"

namespace servodrift
{
  using namespace parameters;

  void FluidParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    prm.declare_entry("Viscosity law", "vogel", Patterns::Selection("vogel|paper-exponential"),
                      "Kinematic viscosity law: vogel, nu = A exp(B/(T + C)) (E16, RV-1, D6), or "
                      "paper-exponential, nu = nu0 exp(-alpha_nu (T - T0)) (E14, paper preset D2). [-]");
    prm.declare_entry("Vogel A", "0.3587e-6", Patterns::Double(0, 1),
                      "Vogel coefficient A (E16). [m^2/s]");
    prm.declare_entry("Vogel B", "593.5", Patterns::Double(0, 1e5),
                      "Vogel coefficient B (E16). [degC]");
    prm.declare_entry("Vogel C", "122.0", Patterns::Double(-273.15, 1e4),
                      "Vogel coefficient C (E16); the law is singular at T = -C. [degC]");
    prm.declare_entry("Reference viscosity", "14.0e-6", Patterns::Double(0, 1),
                      "Kinematic viscosity nu0 at T0 of the exponential law (E14). [m^2/s]");
    prm.declare_entry("Viscosity temperature coefficient", "0.0626", Patterns::Double(0, 1),
                      "alpha_nu of the exponential law (E14; the paper's 0.0626, implausibly steep, "
                      "1.7). [1/degC]");
    prm.declare_entry("Minimum temperature", "-55", Patterns::Double(-273.15, 1000),
                      "Lowest temperature at which the viscosity law holds; any temperature of a "
                      "sweep must lie in the window (E16 is fitted from -40 to 100 degC). [degC]");
    prm.declare_entry("Maximum temperature", "150", Patterns::Double(-273.15, 1000),
                      "Highest temperature at which the viscosity law holds (D3). [degC]");
    prm.declare_entry("Reference density", "850", Patterns::Double(0, 1e5),
                      "Density rho0 at T0 (E15). [kg/m^3]");
    prm.declare_entry("Density temperature coefficient", "5.75e-4", Patterns::Double(0, 0.01),
                      "alpha_rho in rho = rho0 (1 - alpha_rho (T - T0)) (E15). [1/degC]");
    prm.declare_entry("Bulk modulus", "0.7e9", Patterns::Double(0, 1e12),
                      "Effective bulk modulus beta_e at T0, with entrained air and line compliance "
                      "(2.8; dynamics). [Pa]");
    prm.declare_entry("Bulk modulus temperature coefficient", "0.004", Patterns::Double(0, 0.1),
                      "c in beta_e = beta_e0 (1 - c (T - T0)) (2.8). [1/degC]");
    prm.declare_entry("Vapour pressure", "1e3", Patterns::Double(0, 1e7),
                      "Absolute vapour pressure, for cavitation flags (2.8, C12). [Pa]");
    prm.declare_entry("Air release pressure", "20e3", Patterns::Double(0, 1e7),
                      "Absolute pressure below which dissolved air comes out of the oil, 10..30 kPa "
                      "(2.8), for cavitation flags. [Pa]");
    prm.leave_subsection();
  }
} // namespace servodrift
