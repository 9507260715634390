#pragma once
// Steady incompressible Navier-Stokes on the finite-volume mesh of fv_mesh.h: cell-centred,
// collocated velocity and pressure, Rhie-Chow face fluxes, SIMPLEC pressure-velocity coupling
// (the paper's choice, [K22] section 7 of model.md) or coupled (u, v, p) iterations, planar or
// axisymmetric; turbulence models and cavitation. doc/method.md, "Flow core", describes it.
//
// The outer iteration (SimplecSolver::solve_to) reads like OpenFOAM's simpleFoam:
//   while the iteration control goes on (iteration_control.h: convergence, divergence, the cycle
//   and stall tests, the switch to coupled iterations, Anderson acceleration):
//     boundary values and the pressure gradient (boundary_conditions.h)
//     the momentum equations (momentum_equation.h: UEqn)
//     SIMPLEC: the predicted velocities, their Rhie-Chow fluxes (rhie_chow.h) and the pressure
//              correction (pressure_equation.h: pEqn); or one coupled step (coupled_step.h)
//     cavitation (cavitation_model.h), then the turbulence model (turbulence_model.h, k_epsilon.h)
// What it reports of its fields: flow_postprocessing.h.
#include "common/parameters/flow_solver.h"
#include "flow/fv/boundary_conditions.h"
#include "flow/fv/flow_state.h"
#include "flow/fv/newton_ptc.h"

#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace servodrift::flow
{
  struct SolveReport
  {
    unsigned int iterations = 0;
    Residuals residuals;
    double pressure_relaxation = 0; ///< at the end: lowered from the setting by each cycle caught [1]
    /// k-epsilon: cells whose turbulent viscosity the last iteration held at the limit
    /// (set_turbulent_viscosity_limit) instead of the model's value
    std::size_t cells_at_viscosity_limit = 0;
    /// advance: the step's implicit equations met the tolerance (false: its iteration cap stopped
    /// them first, and the step goes on from a partly solved state)
    bool converged = true;
  };

  /// The iteration limit was reached (the fields are usable as a start, not as a result).
  class NotConverged : public std::runtime_error
  {
  public:
    explicit NotConverged(const std::string &what, const Residuals &at_stall = {})
      : std::runtime_error(what)
      , residuals(at_stall)
    {}
    /// where the iterations stopped (below the tolerance where they converged to a state that is
    /// not the model's solution, a limiter held): how near a steady state the stall's fields are
    Residuals residuals;
  };

  class SimplecSolver
  {
  public:
    /// Every boundary patch of the mesh needs a condition and every condition a patch; the flow
    /// needs a driver (an inlet or a moving wall) and an inlet needs an outlet. Throws InputError
    /// naming the mesh and the patch otherwise, or for a non-positive density or viscosity.
    SimplecSolver(const FvMesh &mesh, const FluidProperties &fluid,
                  const std::map<std::string, BoundaryCondition> &boundaries, const FlowSolverParameters &settings);
    ~SimplecSolver();

    /// Continuation: a new total or static pressure on a pressure boundary patch; the next solve
    /// starts from the current fields.
    void set_boundary_pressure(const std::string &patch, double pressure);
    /// The boundary pressure of a pressure patch [Pa].
    double boundary_pressure(const std::string &patch) const;
    /// Continuation between pressure levels: scales the fields as a flow whose Reynolds number
    /// does not matter, by the ratio s of every pressure (boundary pressures included; the
    /// reference 0 stays 0): p by s, velocities and fluxes by sqrt(s), k by s, epsilon by s^(3/2),
    /// mu_t by sqrt(s). Far closer to the new solution than the old fields under new boundary
    /// pressures, whose first iteration would accelerate the inflow far beyond its final speed.
    void scale_pressure_level(double s);
    /// Continuation: starts from the fields of a solver on a mesh of the same topology (the same
    /// template with other dimensions). Throws std::invalid_argument if the cell counts differ.
    void initialize_from(const SimplecSolver &other);

    /// Cavitation (equilibrium, mass-conserving): no pressure below p_cav [Pa, in the solver's own
    /// gauge]. A cell whose pressure would fall below it cavitates: its pressure stays at p_cav and
    /// its liquid fraction gamma < 1 balances its mass (the mixture density rho (gamma + (1 - gamma)
    /// `Vapour density ratio')); it is liquid again where its inflow fills it. Call before each solve
    /// whose reference pressure changes (the vapour pressure is absolute).
    void set_cavitation_pressure(double p_cav);
    /// Turbulence models: the largest turbulent viscosity, as a multiple of the molecular one (1e5 unless
    /// set; applies to the current fields at once). The model's mu_t is held at this limit where it
    /// would exceed it; a converged state with cells at the limit
    /// (SolveReport::cells_at_viscosity_limit) is not the model's solution.
    void set_turbulent_viscosity_limit(double ratio);
    /// Liquid volume fraction per cell (all 1 without cavitation).
    std::vector<double> liquid_fraction() const;

    /// The fields as they are, and a start from fields of a mesh of the same topology (see
    /// initialize_from), or from fields carried from another mesh of the domain without their
    /// fluxes (transfer_fields, grid sequencing), whose fluxes are then those of the face velocities.
    FlowFields fields() const;
    void set_fields(const FlowFields &fields);

    /// Quantities whose change decides convergence with the residuals (a flow rate, a force): the
    /// run converges only when, in addition, none changed by more than `relative_change' of its
    /// magnitude over the last `window' iterations.
    void set_convergence_monitor(std::function<std::vector<double>()> monitor, unsigned int window = 50,
                                 double relative_change = 1e-4);

    /// Iterates until the scaled residuals fall below the tolerance (and the monitored quantities
    /// settle). Throws NotConverged if the iteration limit is reached, std::runtime_error at a NaN
    /// or divergence (naming the iteration; with `failure_output' set, the fields are written there
    /// as VTU first).
    SolveReport solve();
    /// The same to another tolerance, with or without the convergence monitor: a starting state
    /// for a later solve (an intermediate level of a continuation path).
    SolveReport solve_to(double tolerance, bool consult_monitor,
                         const std::function<bool(const Residuals &)> &decided = {});
    std::string failure_output;
    /// Newton-PTC (newton_flow.cc): the same steady discrete equations as solve() (momentum,
    /// continuity, Rhie-Chow's face fluxes, the extrapolated wall pressures) as one system, from the
    /// current fields, to `settings.tolerance' of the scaled residual. Laminar and single phase
    /// (std::invalid_argument otherwise). The fields are left at the last accepted state. Below a
    /// scaled residual of `limiter_hold_residual' the convection limiter is held at its values of that
    /// state (a frozen limiter: differentiable, so Newton converges where Barth-Jespersen's switching
    /// would hold it near 1e-7-1e-6; the answer is then the held limiter's, within about 1e-6 of the
    /// flow rate); 0: never held (exactly SIMPLEC's discrete equations).
    PtcReport solve_newton(const PtcSettings &settings, double limiter_hold_residual = 1e-5);

    /// Time stepping (time_stepping.cc), laminar or with any turbulence model, single phase or
    /// cavitating: one step of dt [s] from the current fields, second-order backward differences
    /// (BDF2) after a first implicit Euler step at the same dt (any other change of the fields in
    /// between starts again with implicit Euler); SIMPLEC iterations until the scaled residuals fall
    /// below `tolerance' or `max_iterations' (a step may end before its tolerance: the report's
    /// residuals say where). Throws std::invalid_argument for dt <= 0 or no iterations,
    /// std::runtime_error at a divergence.
    SolveReport advance(double dt, unsigned int max_iterations, double tolerance);
    /// The time step at which the largest cell Courant number of the current fluxes, half the sum
    /// of |F| over a cell's faces over its mass, dt sum|F|/(2 rho_m V), is `courant' [s].
    double courant_time_step(double courant) const;

    const std::vector<double> &velocity_x() const;
    const std::vector<double> &velocity_y() const;
    const std::vector<double> &pressure() const;
    /// y+ of the first cell centre at a wall, rho u_tau d/mu with the wall shear mu |u_t|/d of the
    /// resolved sublayer, per cell (the largest over its wall faces; 0 away from walls).
    std::vector<double> wall_y_plus() const;
    /// Turbulent viscosity mu_t per cell [Pa*s] (zeros if laminar).
    const std::vector<double> &turbulent_viscosity() const;
    /// The mass that crosses each face per unit time, out of the owner [kg/s, per radian if
    /// axisymmetric]: rho u.S, with cavitation the mixture's (the upwind cell's mixture density).
    const std::vector<double> &mass_flux() const;
    /// Face values at the boundary (index: face) of the last iteration.
    double boundary_pressure(std::size_t face) const;
    Vector2 boundary_velocity(std::size_t face) const;

    /// Volumetric flow out through a patch [m^3/s]: a full revolution if axisymmetric, unit depth if
    /// planar; with cavitation the mixture's mass flow over the liquid density (the liquid's volume flow).
    double flow_rate(const std::string &patch) const;
    /// Area-weighted mean pressure on a patch [Pa].
    double mean_pressure(const std::string &patch) const;
    /// Mass-flux-weighted mean total pressure p + rho |u|^2/2 through a patch [Pa].
    double mean_total_pressure(const std::string &patch) const;
    /// The lowest cell or boundary-face pressure [Pa].
    double minimum_pressure() const;
    /// Integral of (p - p_reference) n . e over a patch, n out of the fluid [N]: the pressure force
    /// of the fluid on the wall along e (a full revolution if axisymmetric).
    double pressure_force(const std::string &patch, const Vector2 &direction, double p_reference = 0) const;

    /// Mass balance of the converged fields: the largest |sum of face mass fluxes| of a cell and the
    /// net mass flux out of the domain, both relative to the throughput (inflow) [1]. With cavitation
    /// the mixture's mass, which the liquid fraction of a cavitating cell balances.
    double max_cell_imbalance() const;
    double net_imbalance() const;
    double throughput() const; ///< inflow mass flux [kg/s per radian or per unit depth]

    /// Pressure, velocity, cell id, y+ and, on boundary line cells, the boundary id, as VTU (VTK
    /// library); the turbulence model's fields (k-epsilon: k, epsilon (epsilon~ for Launder-Sharma)
    /// and mu_t) and with cavitation the liquid fraction.
    void write_vtu(const std::string &filename) const;

  private:
    struct Implementation;
    class NewtonProblem; ///< the residual and Jacobian of solve_newton
    std::unique_ptr<Implementation> impl;
  };
} // namespace servodrift::flow
