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
                      "'reduced-order' is E21-E23; 'field' is the axisymmetric finite-volume solution of "
                      "meshes/fixed_orifice.geo and meshes/nozzle_flapper.geo (4.2, D11), the costlier of the "
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
    prm.declare_entry("Nozzle discharge coefficient", "0.64", Patterns::Double(0, 1),
                      "Inertial discharge coefficient C_d,inf of the nozzle curtain (E22). [1]");
    prm.declare_entry("Control cavity volume", "1.0e-7", Patterns::Double(0, 1),
                      "Volume V_0 of each control cavity with its passages (E33; dynamics). [m^3]");
    prm.declare_entry("Field mesh resolution", "1", Patterns::Double(0.25, 8),
                      "Field level: multiplies every cell count of meshes/fixed_orifice.geo (30 cells "
                      "across the bore radius at 1) and meshes/nozzle_flapper.geo (20 across the gap "
                      "at 1). [1]");
    prm.declare_entry("Field grid sequencing", "true", Patterns::Bool(),
                      "Field level: a case that starts from rest on a mesh of resolution 1.5 or finer is "
                      "first solved on the mesh of half that resolution and starts from those fields "
                      "(fewer, cheaper iterations; the answer is the fine mesh's). false: the laminar "
                      "start-up on the fine mesh itself. [-]");
    prm.declare_entry("Field continuation ratio", "3", Patterns::Double(1.1, 1e6),
                      "Field level: largest ratio of successive pressure levels on a case's solution "
                      "path (from its start-up or the last converged case; larger steps go through "
                      "geometric intermediate levels). Laminar cavitating nozzle cases have more than one "
                      "steady solution; small enough steps follow the quasi-static branch "
                      "(doc/validation.md). [1]");
    prm.declare_entry("Field turbulent viscosity limit", "0.1", Patterns::Double(1e-6, 1e6),
                      "Field level, turbulence models: the largest mu_t/mu on a case's solution path, as a "
                      "multiple of its ideal-velocity Reynolds number (E17 for the orifice, 2 h sqrt(2 "
                      "dp/rho)/nu for the nozzle; a round jet's is about 0.015 Re, Pope 2000). It bounds "
                      "transients of a cavity only: a case that converges with mu_t at the limit anywhere is "
                      "flagged as not converged. [1]");
    prm.declare_entry("Field plenum size", "6", Patterns::Double(2, 100),
                      "Field level: radius and length of the fixed orifice's upstream plenum, in bore "
                      "radii D_0/2. [1]");
    prm.declare_entry("Field chamber length", "30", Patterns::Double(4, 1000),
                      "Field level: length of the fixed orifice's downstream chamber (radius 8 bore "
                      "radii), in bore radii D_0/2; the chamber ends in a wall and the outlet is its "
                      "side. A shorter chamber lets the wall jet's recirculation at the outlet corner "
                      "cycle in more cases; C_d depends little on the length (doc/validation.md). [1]");
    prm.declare_entry("Field outlet radius", "4", Patterns::Double(1.5, 100),
                      "Field level: radius of the nozzle-flapper case's radial outlet (return "
                      "pressure), in land radii D_land/2. [1]");
    prm.declare_entry("Field cavitation", "true", Patterns::Bool(),
                      "Field level: the cases model cavitation (equilibrium, mass-conserving: no absolute "
                      "pressure below `Fluid/Vapour pressure'; a cell that would go below holds it and its "
                      "liquid fraction carries the mass). Without it (single-phase, D11 as printed) the "
                      "suction ring at the land's inner edge falls far below zero absolute at RV-1's "
                      "pressures (C12). [-]");
    prm.declare_entry("Field time average", "true", Patterns::Bool(),
                      "Field level: a case whose steady iteration does not converge (a jet or a cavity that "
                      "oscillates has no steady solution) is marched in time from where it stopped (BDF2, "
                      "URANS if turbulent) "
                      "and reported by its time average, flagged 5, its spread in "
                      "flow/<geometry>_time_averages.csv. false: flagged 2, the reduced-order value "
                      "stands in. [-]");
    prm.declare_entry("Field time step Courant number", "1", Patterns::Double(0.05, 50),
                      "Field level, time average: the time step, constant, at this largest cell Courant "
                      "number of the fields it starts from. The means do not depend on it (1, 0.5 and 0.25 "
                      "agree within their standard errors); a smaller one needs proportionally more `Field "
                      "time steps', or the first window may not span the flow's cycle (doc/validation.md). [1]");
    prm.declare_entry("Field time step iterations", "50", Patterns::Integer(1, 100000),
                      "Field level, time average: the SIMPLEC iterations of a time step at most, to bring its "
                      "equations to scaled residuals of 1e-4. Most steps take 2-15; a step the cap stops is "
                      "counted (flow/<geometry>_time_averages.csv). Raised to 200, hot cavitating cases "
                      "cost 12-23 % more and their means move by less than their standard errors "
                      "(doc/validation.md). [1]");
    prm.declare_entry("Field time step halvings", "0", Patterns::Integer(0, 10),
                      "Field level, time average: a march with more than 10 % of its averaged steps "
                      "capped (`Field time step iterations') is marched again from where it ended at half "
                      "the Courant number, at most this many times; each halving doubles a march's cost. "
                      "0: flagged 2 at once. For steps too long for the cap (doc/method.md). [1]");
    prm.declare_entry("Field time steps", "2000", Patterns::Integer(20, 10000000),
                      "Field level, time average: the time steps marched first. [1]");
    prm.declare_entry("Field time steps limit", "10000", Patterns::Integer(20, 10000000),
                      "Field level, time average: a mean still uncertain beyond `Field time average "
                      "uncertainty limit' after `Field time steps' is marched on, its averaged time "
                      "lengthened to what its standard error (falling as 1/sqrt of that time) asks, up to "
                      "this many steps in all; at least `Field time steps'. [1]");
    prm.declare_entry("Field time average uncertainty limit", "0.01", Patterns::Double(0, 10),
                      "Field level, time average: the largest standard error of the mean of C_d and of the "
                      "flapper force (batch means), relative to the means, for which the mean stands for the "
                      "case (flag 5); beyond it flag 2, the average only listed. The valve feels the mean, "
                      "not the pilot's MHz cycles (doc/method.md). Default: the 1 % allowed the default "
                      "mesh. [1]");
    prm.declare_entry("Field averaged fraction", "0.5", Patterns::Double(0.1, 1),
                      "Field level, time average: the last this fraction of the time steps is averaged "
                      "(the first part lets the start from the stalled iterate die out). [1]");
    const char *models = "automatic|laminar|k-epsilon|k-epsilon-launder-sharma|k-omega-sst";
    prm.declare_entry("Fixed orifice flow model", "automatic", Patterns::Selection(models),
                      "Field level: flow model of the fixed-orifice cases (D11): laminar, k-epsilon (the "
                      "two-layer standard model of `Flow solver/Turbulence model'), "
                      "k-epsilon-launder-sharma, k-omega-sst, or automatic: laminar below the fixed orifice transition "
                      "Reynolds number (E17, ideal velocity), k-epsilon from it. [-]");
    prm.declare_entry("Fixed orifice transition Reynolds number", "1000", Patterns::Double(0, 1e9),
                      "Field level, automatic flow model: Re_0 (E17) from which the fixed orifice runs "
                      "k-epsilon. Below the default the laminar solution is steady and follows "
                      "Lichtarowicz (E21); above, it stops converging (the jet is unsteady) while the "
                      "two-layer model still gives the laminar C_d just above the transition "
                      "(doc/validation.md). [1]");
    prm.declare_entry("Nozzle flow model", "k-epsilon", Patterns::Selection(models),
                      "Field level: flow model of the nozzle-flapper cases (D11), as for the fixed "
                      "orifice; automatic switches at the nozzle transition Reynolds number. k-epsilon "
                      "for every case (the paper's model) keeps the flapper force smooth in gap and "
                      "temperature: with automatic, the cases around the null change model with "
                      "temperature and K_f(T) jumps (doc/validation.md). [-]");
    prm.declare_entry("Nozzle transition Reynolds number", "2000", Patterns::Double(0, 1e9),
                      "Field level, automatic flow model: the ideal-velocity gap Reynolds number 2 h "
                      "sqrt(2 dp/rho)/nu from which the nozzle-flapper case runs k-epsilon. [1]");
    prm.declare_entry("Nozzle stall window", "250", Patterns::Integer(0, 10000000),
                      "Field level: `Flow solver/Stall window' for the nozzle-flapper cases (the fixed "
                      "orifice keeps the Flow solver's). Their SIMPLEC stalls (a cavity's edge flickering) "
                      "are converged quickly by coupled iterations on the nozzle's small mesh, so a shorter "
                      "window switches sooner, with the same answer. 0: never. [1]");
    prm.declare_entry("Model-form alternatives", "",
                      Patterns::List(Patterns::Selection("laminar|k-epsilon|k-epsilon-launder-sharma|k-omega-sst"), 0, 3),
                      "Field level: other flow models whose pilot tables the flow stage also computes "
                      "(tables/<table>.<model>.csv); the system stage reports the spread of C_dn, the "
                      "flapper force and K_f between them and the default as the model-form uncertainty "
                      "(system/model_form_spread.csv, a band in the report). laminar: only where the "
                      "transition Reynolds number allows it. Each costs a flow stage. Empty: none. [-]");
    prm.declare_entry("Bore sensitivity", "auto", Patterns::Selection("auto|on|off"),
                      "Whether the flow stage also tabulates the pilot flows at bores one `Bore "
                      "sensitivity step' wider (tables/*_bore.csv), for a side built to another bore "
                      "(Asymmetry, Tolerances); without them, the closed forms' ratio E21/E22 "
                      "(doc/method.md \"Asymmetric valve\"). auto: at the field level when a bore is "
                      "toleranced or deviates. [-]");
    prm.declare_entry("Bore sensitivity step", "4e-6", Patterns::Double(1e-7, 5e-5),
                      "Diameter step of the bore-sensitivity tables, the same for the fixed orifice and "
                      "the nozzle: large enough that the field level's discretisation noise between two "
                      "meshes stays below the effect, small against the bores. [m]");
    prm.declare_entry("Fixed orifice law", "lichtarowicz", Patterns::Selection("lichtarowicz|paper-fit"),
                      "Reduced-order fixed-orifice discharge coefficient: lichtarowicz (E21, RV-1) or "
                      "paper-fit (the paper's cubic E26 in Re_0, clamped to its window Re_0 in "
                      "[974, 11688] and flagged outside it, C6; paper preset D2). [-]");
    prm.declare_entry("Nozzle law", "curtain", Patterns::Selection("curtain|paper-fit"),
                      "Reduced-order nozzle discharge: curtain (E22, inertial + laminar land, RV-1) or "
                      "paper-fit (the T-part of E27, C_dn = 0.5841 + 3.49e-4 T - 2.26e-6 T^2; paper "
                      "preset D2). [-]");
    prm.declare_entry("Flapper force law", "momentum", Patterns::Selection("momentum|paper-table"),
                      "Reduced-order flapper force: momentum (E23, RV-1) or paper-table (E23 scaled so "
                      "that the flow-force stiffness follows the paper's K_f(T) table of section 3 item "
                      "10; paper preset D2). [-]");
    prm.leave_subsection();
  }
} // namespace servodrift
