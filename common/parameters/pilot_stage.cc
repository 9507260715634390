#include "common/parameters/pilot_stage.h"

#include "common/parameters/parameter_helpers.h"

namespace servodrift
{
  using namespace parameters;

  void PilotStageParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    prm.declare_entry("Model level", "field", Patterns::Selection("reduced-order|field"),
                      "Which model computes the fixed_orifice and nozzle_flapper tables (D13): "
                      "'reduced-order' is E21-E23 (subsection Reduced order); 'field' is the axisymmetric "
                      "finite-volume solution of meshes/fixed_orifice.geo and meshes/nozzle_flapper.geo "
                      "(4.2, D11; subsections Field mesh, Field solution, Time average), the costlier of the "
                      "two (doc/performance.md). [-]");
    prm.declare_entry("Fixed orifice diameter", "0.225e-3", Patterns::Double(0, 0.1),
                      "Bore diameter D_0 of each fixed (inlet) orifice (E17, E31). [m]");
    prm.declare_entry("Fixed orifice length", "0.50e-3", Patterns::Double(0, 0.1),
                      "Bore length l_0 of each fixed orifice; l_0/D_0 enters E21. [m]");
    prm.declare_entry("Nozzle diameter", "0.40e-3", Patterns::Double(0, 0.1),
                      "Nozzle bore diameter D_N (E18, E22, E23, E32). [m]");
    prm.declare_entry("Land diameter", "0.70e-3", Patterns::Double(0, 0.1),
                      "Outer diameter D_land of the flat nozzle tip (land), above D_N (E22). [m]");
    prm.declare_entry("Null gap", "40e-6", Patterns::Double(0, 0.1),
                      "Nozzle-flapper gap x0 with the flapper centred, at T0; at most a quarter of the "
                      "nozzle diameter so that the curtain, not the bore, throttles (E32). [m]");
    prm.declare_entry("Nozzle seat span", "13.0e-3", Patterns::Double(0, 1),
                      "Body span between the two nozzle seats; with the nozzle length and the flapper "
                      "width it sets the thermal change of x0 (2.3). [m]");
    prm.declare_entry("Nozzle length", "6.0e-3", Patterns::Double(0, 1),
                      "Length of each nozzle from its seat in the body to its tip (2.3). [m]");
    prm.declare_entry("Control cavity volume", "1.0e-7", Patterns::Double(0, 1),
                      "Volume V_0 of each control cavity with its passages (E33; dynamics). [m^3]");
    PilotReducedOrderParameters::declare_parameters(prm);
    PilotFieldMeshParameters::declare_parameters(prm);
    PilotFieldSolutionParameters::declare_parameters(prm);
    PilotTimeAverageParameters::declare_parameters(prm);
    BoreSensitivityParameters::declare_parameters(prm);
    prm.leave_subsection();
  }

  void PilotReducedOrderParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    prm.declare_entry("Fixed orifice law", "lichtarowicz", Patterns::Selection("lichtarowicz|paper-fit"),
                      "Fixed-orifice discharge coefficient: lichtarowicz (E21, RV-1) or paper-fit (the "
                      "paper's cubic E26 in Re_0, clamped to its window Re_0 in [974, 11688] and flagged "
                      "outside it, C6; paper preset D2). [-]");
    prm.declare_entry("Nozzle law", "curtain", Patterns::Selection("curtain|paper-fit"),
                      "Nozzle discharge: curtain (E22, inertial + laminar land, RV-1) or paper-fit (the "
                      "T-part of E27, C_dn = 0.5841 + 3.49e-4 T - 2.26e-6 T^2; paper preset D2). [-]");
    prm.declare_entry("Nozzle discharge coefficient", "0.64", Patterns::Double(0, 1),
                      "Inertial discharge coefficient C_d,inf of the nozzle curtain (E22). [1]");
    prm.declare_entry("Flapper force law", "momentum", Patterns::Selection("momentum|paper-table"),
                      "Flapper force: momentum (E23, RV-1) or paper-table (E23 scaled so that the "
                      "flow-force stiffness follows the paper's K_f(T) table of section 3 item 10; paper "
                      "preset D2). [-]");
    prm.leave_subsection();
  }

  void BoreSensitivityParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    prm.declare_entry("Tables", "auto", Patterns::Selection("auto|on|off"),
                      "Whether the flow stage also tabulates the pilot flows at bores one `Step' wider "
                      "(tables/*_bore.csv), for a side built to another bore (Asymmetry, Tolerances); "
                      "without them, the closed forms' ratio E21/E22 (doc/method.md \"Asymmetric valve\"). "
                      "auto: at the field level when a bore is toleranced or deviates. [-]");
    prm.declare_entry("Step", "4e-6", Patterns::Double(1e-7, 5e-5),
                      "Diameter step of the bore-sensitivity tables, the same for the fixed orifice and "
                      "the nozzle: large enough that the field level's discretisation noise between two "
                      "meshes stays below the effect, small against the bores. [m]");
    prm.leave_subsection();
  }
} // namespace servodrift
