#include "common/parameters/spring_tube.h"

#include "common/parameters/parameter_helpers.h"

namespace servodrift
{
  using namespace parameters;

  void SpringTubeParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    prm.declare_entry("Model level", "field", Patterns::Selection("reduced-order|field"),
                      "Which model computes the spring_tube table: 'reduced-order' is the beam closed "
                      "form E11-E13 (D13); 'field' is linear elasticity of the tube, axisymmetric with "
                      "Fourier harmonic n = 1, clamped base, rigid top (D12, model.md 4.3). [-]");
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
    prm.declare_entry("Base flange diameter", "0", Patterns::Double(0, 1),
                      "Outer diameter of the base flange, one piece with the tube (field level; used "
                      "when the flange height is above 0; must exceed the outer diameter D). [m]");
    prm.declare_entry("Base flange height", "0", Patterns::Double(0, 1),
                      "Height of the base flange below the thin section; its bottom face is clamped "
                      "(field level; 0: no flange, the thin section is clamped at its base). [m]");
    prm.declare_entry("Top collar diameter", "0", Patterns::Double(0, 1),
                      "Outer diameter of the top collar, one piece with the tube (field level; used "
                      "when the collar height is above 0; must exceed the outer diameter D). [m]");
    prm.declare_entry("Top collar height", "0", Patterns::Double(0, 1),
                      "Height of the top collar above the thin section; its top face is the rigid "
                      "armature seat (field level; 0: no collar, the thin section's top is rigid). [m]");
    prm.declare_entry("Field element degree", "2", Patterns::Integer(1, 4),
                      "Degree of the FE_Q elements of the displacement harmonics (field level). Degree 1 "
                      "locks in bending of the thin wall; 2 or more. [1]");
    prm.declare_entry("Field wall layers", "4", Patterns::Integer(1, 64),
                      "Element layers through the tube wall at resolution 1 (field level; issue 6 asks "
                      "for at least 3, or higher-order elements). [1]");
    prm.declare_entry("Field aspect ratio", "4", Patterns::Double(0.5, 20),
                      "Axial over radial element size in the thin wall (field level); flanges and "
                      "collar use the same sizes. [1]");
    prm.declare_entry("Field mesh resolution", "1", Patterns::Double(0.25, 16),
                      "Scales the field model's element counts (wall layers x resolution, element "
                      "sizes / resolution), for convergence studies. [1]");
    prm.leave_subsection();
  }
} // namespace servodrift
