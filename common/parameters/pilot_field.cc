#include "common/parameters/pilot_field.h"

#include "common/parameters/parameter_helpers.h"

namespace servodrift
{
  using namespace parameters;

  void PilotFieldMeshParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    prm.declare_entry("Resolution", "1", Patterns::Double(0.25, 8),
                      "Multiplies every cell count of meshes/fixed_orifice.geo (30 cells across the bore "
                      "radius at 1) and meshes/nozzle_flapper.geo (20 across the gap at 1). [1]");
    prm.declare_entry("Grid sequencing", "true", Patterns::Bool(),
                      "A case that starts from rest on a mesh of resolution 1.5 or finer is first solved on "
                      "the mesh of half that resolution and starts from those fields (fewer, cheaper "
                      "iterations; the answer is the fine mesh's). false: the laminar start-up on the fine "
                      "mesh itself. [-]");
    prm.declare_entry("Plenum size", "6", Patterns::Double(2, 100),
                      "Radius and length of the fixed orifice's upstream plenum, in bore radii D_0/2. [1]");
    prm.declare_entry("Chamber length", "30", Patterns::Double(4, 1000),
                      "Length of the fixed orifice's downstream chamber (radius 8 bore radii), in bore radii "
                      "D_0/2; the chamber ends in a wall and the outlet is its side. A shorter chamber lets "
                      "the wall jet's recirculation at the outlet corner cycle in more cases; C_d depends "
                      "little on the length (doc/validation.md). [1]");
    prm.declare_entry("Outlet radius", "4", Patterns::Double(1.5, 100),
                      "Radius of the nozzle-flapper case's radial outlet (return pressure), in land radii "
                      "D_land/2. [1]");
    prm.leave_subsection();
  }

  void PilotFieldSolutionParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    const char *models = "automatic|laminar|k-epsilon|k-epsilon-launder-sharma|k-omega-sst";
    prm.declare_entry("Fixed orifice flow model", "automatic", Patterns::Selection(models),
                      "Flow model of the fixed-orifice cases (D11): laminar, k-epsilon (the two-layer "
                      "standard model of `Flow solver/Turbulence model'), k-epsilon-launder-sharma, "
                      "k-omega-sst, or automatic: laminar below the fixed orifice transition Reynolds number "
                      "(E17, ideal velocity), k-epsilon from it. [-]");
    prm.declare_entry("Fixed orifice transition Reynolds number", "1000", Patterns::Double(0, 1e9),
                      "Automatic flow model: Re_0 (E17) from which the fixed orifice runs k-epsilon. Below "
                      "the default the laminar solution is steady and follows Lichtarowicz (E21); above, it "
                      "stops converging (the jet is unsteady) while the two-layer model still gives the "
                      "laminar C_d just above the transition (doc/validation.md). [1]");
    prm.declare_entry("Nozzle flow model", "k-epsilon", Patterns::Selection(models),
                      "Flow model of the nozzle-flapper cases (D11), as for the fixed orifice; automatic "
                      "switches at the nozzle transition Reynolds number. k-epsilon for every case (the "
                      "paper's model) keeps the flapper force smooth in gap and temperature: with automatic, "
                      "the cases around the null change model with temperature and K_f(T) jumps "
                      "(doc/validation.md). [-]");
    prm.declare_entry("Nozzle transition Reynolds number", "2000", Patterns::Double(0, 1e9),
                      "Automatic flow model: the ideal-velocity gap Reynolds number 2 h sqrt(2 dp/rho)/nu "
                      "from which the nozzle-flapper case runs k-epsilon. [1]");
    prm.declare_entry("Cavitation", "true", Patterns::Bool(),
                      "The cases model cavitation (equilibrium, mass-conserving: no absolute pressure below "
                      "`Fluid/Vapour pressure'; a cell that would go below holds it and its liquid fraction "
                      "carries the mass). Without it (single-phase, D11 as printed) the suction ring at the "
                      "land's inner edge falls far below zero absolute at RV-1's pressures (C12). [-]");
    prm.declare_entry("Continuation ratio", "3", Patterns::Double(1.1, 1e6),
                      "Largest ratio of successive pressure levels on a case's solution path (from its "
                      "start-up or the last converged case; larger steps go through geometric intermediate "
                      "levels). Laminar cavitating nozzle cases have more than one steady solution; small "
                      "enough steps follow the quasi-static branch (doc/validation.md). [1]");
    prm.declare_entry("Turbulent viscosity limit", "0.1", Patterns::Double(1e-6, 1e6),
                      "Turbulence models: the largest mu_t/mu on a case's solution path, as a multiple of "
                      "its ideal-velocity Reynolds number (E17 for the orifice, 2 h sqrt(2 dp/rho)/nu for "
                      "the nozzle; a round jet's is about 0.015 Re, Pope 2000). It bounds transients of a "
                      "cavity only: a case that converges with mu_t at the limit anywhere is flagged as not "
                      "converged. [1]");
    prm.declare_entry("Nozzle stall window", "250", Patterns::Integer(0, 10000000),
                      "`Flow solver/Stall window' for the nozzle-flapper cases (the fixed orifice keeps the "
                      "Flow solver's). Their SIMPLEC stalls (a cavity's edge flickering) are converged "
                      "quickly by coupled iterations on the nozzle's small mesh, so a shorter window "
                      "switches sooner, with the same answer. 0: never. [1]");
    prm.declare_entry("Model-form alternatives", "",
                      Patterns::List(Patterns::Selection("laminar|k-epsilon|k-epsilon-launder-sharma|k-omega-sst"), 0, 3),
                      "Other flow models whose pilot tables the flow stage also computes "
                      "(tables/<table>.<model>.csv); the system stage reports the spread of C_dn, the "
                      "flapper force and K_f between them and the default as the model-form uncertainty "
                      "(system/model_form_spread.csv, a band in the report). laminar: only where the "
                      "transition Reynolds number allows it. Each costs a flow stage. Empty: none. [-]");
    prm.leave_subsection();
  }

  void PilotTimeAverageParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    prm.declare_entry("Enabled", "true", Patterns::Bool(),
                      "A field case whose steady iteration does not converge (a jet or a cavity that "
                      "oscillates has no steady solution) is marched in time from where it stopped (BDF2, "
                      "URANS if turbulent) and reported by its time average, flagged 5, its spread in "
                      "flow/<geometry>_time_averages.csv. false: flagged 2, the reduced-order value stands "
                      "in. [-]");
    prm.declare_entry("Courant number", "1", Patterns::Double(0.05, 50),
                      "The time step, constant, at this largest cell Courant number of the fields it starts "
                      "from. The means do not depend on it (1, 0.5 and 0.25 agree within their standard "
                      "errors); a smaller one needs proportionally more `Steps', or the first window may "
                      "not span the flow's cycle (doc/validation.md). [1]");
    prm.declare_entry("Step iterations", "50", Patterns::Integer(1, 100000),
                      "The SIMPLEC iterations of a time step at most, to bring its equations to scaled "
                      "residuals of 1e-4. Most steps take 2-15; a step the cap stops is counted "
                      "(flow/<geometry>_time_averages.csv). Raised to 200, hot cavitating cases cost 12-23 % "
                      "more and their means move by less than their standard errors (doc/validation.md). [1]");
    prm.declare_entry("Step halvings", "0", Patterns::Integer(0, 10),
                      "A march with more than 10 % of its averaged steps capped (`Step iterations') is "
                      "marched again from where it ended at half the Courant number, at most this many "
                      "times; each halving doubles a march's cost. 0: flagged 2 at once. For steps too long "
                      "for the cap (doc/method.md). [1]");
    prm.declare_entry("Steps", "2000", Patterns::Integer(20, 10000000), "The time steps marched first. [1]");
    prm.declare_entry("Steps limit", "10000", Patterns::Integer(20, 10000000),
                      "A mean still uncertain beyond `Uncertainty limit' after `Steps' is marched on, its "
                      "averaged time lengthened to what its standard error (falling as 1/sqrt of that time) "
                      "asks, up to this many steps in all; at least `Steps'. [1]");
    prm.declare_entry("Averaged fraction", "0.5", Patterns::Double(0.1, 1),
                      "The last this fraction of the time steps is averaged (the first part lets the start "
                      "from the stalled iterate die out). [1]");
    prm.declare_entry("Uncertainty limit", "0.01", Patterns::Double(0, 10),
                      "The largest standard error of the mean of C_d and of the flapper force (batch means), "
                      "relative to the means, for which the mean stands for the case (flag 5); beyond it "
                      "flag 2, the average only listed. The valve feels the mean, not the pilot's MHz cycles "
                      "(doc/method.md). Default: the 1 % allowed the default mesh. [1]");
    prm.leave_subsection();
  }
} // namespace servodrift
