#include "common/parameters/flow_solver.h"

#include "common/parameters/parameter_helpers.h"

namespace servodrift
{
  using namespace parameters;

  void FlowSolverParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    prm.declare_entry("Convection scheme", "bounded-linear-upwind",
                      Patterns::Selection("upwind|bounded-linear-upwind"),
                      "Face values of the convected velocity: upwind (first order, as in [K22]) or "
                      "bounded-linear-upwind (second order, the upwind cell's gradient limited by "
                      "Barth-Jespersen, as a deferred correction). [-]");
    prm.declare_entry("Velocity relaxation", "0.9", Patterns::Double(0.01, 1),
                      "Under-relaxation alpha_u of the momentum equations (SIMPLEC). [1]");
    prm.declare_entry("Pressure relaxation", "0.7", Patterns::Double(0.01, 1),
                      "Under-relaxation of the pressure correction. SIMPLEC needs none (1) between a "
                      "velocity inlet and an outlet; between pressure boundaries (the valve's cases) it "
                      "settles into a two-iteration cycle without, which the default removes (doc/method.md). [1]");
    prm.declare_entry("Pressure-velocity coupling", "simplec-then-coupled",
                      Patterns::Selection("simplec|coupled|simplec-then-coupled"),
                      "simplec: segregated (momentum, then the pressure correction; the paper's choice). "
                      "coupled: u, v and p as one linear system per outer iteration (UMFPACK LU): the same "
                      "converged fields in fewer, much costlier iterations. simplec-then-coupled: SIMPLEC, "
                      "coupled iterations from where it stalls (`Stall window', then judged on the `Cycle "
                      "window'), SIMPLEC again if they stall too (doc/method.md). [-]");
    prm.declare_entry("Momentum solver", "bicgstab-jacobi",
                      Patterns::Selection("bicgstab-jacobi|bicgstab-gauss-seidel|bicgstab-ilu|direct"),
                      "Linear solver of the momentum equations: BiCGSTAB (Eigen) preconditioned by Jacobi, a "
                      "symmetric Gauss-Seidel sweep or an incomplete LU (ILUT), or UMFPACK LU. bench/bench_flow "
                      "compares them. The sweep is the cheapest per outer iteration (RV-1's flow stage 0.88 x), "
                      "but Launder-Sharma's cavitating orifice diverges with it (doc/method.md). [-]");
    prm.declare_entry("Turbulence solver", "bicgstab-jacobi",
                      Patterns::Selection("bicgstab-jacobi|bicgstab-gauss-seidel|bicgstab-ilu"),
                      "Linear solver of the k, epsilon and omega equations: BiCGSTAB preconditioned by Jacobi, a "
                      "symmetric Gauss-Seidel sweep or ILUT. With the sweep, Launder-Sharma's impinging jet "
                      "stalls instead of converging (doc/method.md). [-]");
    prm.declare_entry("Linear solver tolerance", "1e-3", Patterns::Double(1e-12, 0.5),
                      "BiCGSTAB (momentum, k, epsilon) stops when the residual of the correction has fallen by "
                      "this factor. Looser saves time per iteration but stalls more cases and slows Anderson "
                      "acceleration. The pressure correction is always solved to round-off, "
                      "for mass conservation. [1]");
    prm.declare_entry("Tolerance", "1e-6", Patterns::Double(1e-15, 1),
                      "The run converges when the scaled residuals of both momentum equations and of "
                      "continuity fall below this. [1]");
    prm.declare_entry("Maximum iterations", "5000", Patterns::Integer(1, 10000000),
                      "Outer iterations (SIMPLEC or coupled); a run that has not converged by then fails. [1]");
    prm.declare_entry("Stall window", "1000", Patterns::Integer(0, 10000000),
                      "A run whose largest scaled residual has not fallen by half from one window of this "
                      "many iterations to the next has stalled (a cycle, not a slow convergence) and fails "
                      "then, without waiting for the iteration limit, or with `Pressure-velocity coupling' "
                      "simplec-then-coupled goes on with coupled iterations (and, if they stall, with SIMPLEC "
                      "judged on 4 such windows). 0: never. [1]");
    prm.declare_entry("Cycle window", "200", Patterns::Integer(0, 10000000),
                      "A run whose largest scaled residual has not fallen by half from one window of this "
                      "many iterations to the next is caught in a cycle (cells at a cavity's edge switching "
                      "between liquid and vapour): its pressure relaxation is lowered by 0.7, down to 0.3, "
                      "which changes the path, not the converged fields. 0: never. [1]");
    prm.declare_entry("Report interval", "0", Patterns::Integer(0, 10000000),
                      "Print the residuals every this many iterations on stderr (0: only at the end). [1]");
    prm.declare_entry("Monitor iterations", "50", Patterns::Integer(1, 100000),
                      "Where a stage monitors results (the pilot stage: the flow rate and the flapper "
                      "force), a run converges only when they also changed by less than the monitor "
                      "tolerance over this many iterations. [1]");
    prm.declare_entry("Monitor tolerance", "1e-4", Patterns::Double(1e-14, 1),
                      "Largest relative change of a monitored result over the monitor iterations. [1]");
    prm.declare_entry("Turbulence model", "laminar",
                      Patterns::Selection("laminar|k-epsilon|k-epsilon-launder-sharma|k-omega-sst"),
                      "laminar; k-epsilon: the standard model with a two-layer wall treatment (Wolfshtein's "
                      "one-equation model near the wall); k-epsilon-launder-sharma: the Launder-Sharma "
                      "low-Reynolds model; k-omega-sst: Menter's SST (2003). All are integrated to the wall "
                      "(first cell at y+ of order 1); constants and references in doc/method.md. Where a "
                      "stage chooses per case, its own entry overrides this. [-]");
    prm.declare_entry("Turbulence relaxation", "0.9", Patterns::Double(0.01, 1),
                      "Under-relaxation of the k and epsilon equations. [1]");
    prm.declare_entry("Turbulent viscosity relaxation", "0.5", Patterns::Double(0.01, 1),
                      "Under-relaxation of the turbulent viscosity mu_t between iterations. Too weak a "
                      "relaxation (values well above the default) lets the momentum-mu_t coupling of the "
                      "valve's cases settle into a two-iteration cycle whose mass imbalance stops falling "
                      "(doc/method.md). [1]");
    prm.declare_entry("Vapour density ratio", "1e-3", Patterns::Double(1e-8, 0.5),
                      "Where a stage models cavitation: density of the vapour in a cavitating cell over the "
                      "liquid's. The real ratio is about 1e-5; at 1e-3 the vapour's momentum is still "
                      "negligible and the liquid fraction stays well conditioned. [1]");
    prm.declare_entry("Realizability coefficient", "0.6", Patterns::Double(0, 1),
                      "k-epsilon models (two-layer and Launder-Sharma): Durbin's bound on the turbulence time "
                      "scale, k/epsilon <= alpha/(sqrt(6) C_mu |S|), which keeps the modelled normal stresses >= 0 where the strain "
                      "is strong (the orifice's sharp entry, the jet's stagnation on the flapper); without it "
                      "the models' production runs away there, and Launder-Sharma's hot cases cycle. 0 turns it "
                      "off (the textbook models). [1]");
    prm.declare_entry("Acceleration depth", "10", Patterns::Integer(0, 50),
                      "Anderson acceleration of the SIMPLEC iteration: each new iterate is the combination of "
                      "the last this many SIMPLEC updates whose change is smallest in the least-squares sense "
                      "(the fixed point is the same; only the path to it changes). 0: plain SIMPLEC. [1]");
    prm.declare_entry("Acceleration start", "1e-2", Patterns::Double(0, 1e10),
                      "Anderson acceleration begins once the largest scaled residual is below this (the "
                      "first iterations from rest are far from the linear convergence it accelerates). [1]");
    prm.leave_subsection();
  }
} // namespace servodrift
