#include "flow/fv/simplec.h"

#include "common/error.h"
#include "flow/fv/continuity.h"
#include "flow/fv/flow_postprocessing.h"
#include "flow/fv/rhie_chow.h"
#include "flow/fv/simplec_implementation.h"
#include "flow/fv/vtu_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace servodrift::flow
{
  namespace
  {
    const FluidProperties &checked(const FluidProperties &fluid)
    {
      if (!(fluid.density > 0))
        throw InputError("flow: density " + format_number(fluid.density) + " kg/m^3 must be > 0");
      if (!(fluid.viscosity > 0))
        throw InputError("flow: viscosity " + format_number(fluid.viscosity) + " Pa*s must be > 0");
      return fluid;
    }

    /// A run that fails: its fields written as VTU where `failure_output' says, then the error.
    template <class Error, class... Details>
    [[noreturn]] void fail(const SimplecSolver &solver, const FvMesh &mesh, const std::string &reason,
                           const Details &...details)
    {
      const std::string &vtu = solver.failure_output;
      if (!vtu.empty())
        solver.write_vtu(vtu);
      throw Error("flow: " + mesh.source + ": " + reason + (vtu.empty() ? "" : "; fields in " + vtu), details...);
    }
  } // namespace

  SimplecSolver::Implementation::Implementation(const FvMesh &mesh_, const FluidProperties &fluid_,
                                                const std::map<std::string, BoundaryCondition> &conditions,
                                                const FlowSolverParameters &settings_)
    : mesh(mesh_)
    , fluid(checked(fluid_))
    , settings(settings_)
    , boundaries(mesh_, fluid, conditions)
    , state(mesh_)
    , pattern(mesh_)
    , momentum(mesh_, pattern, fluid, settings)
    , pressure(mesh_, pattern, fluid.density)
    , coupled(mesh_, fluid.density)
    , cavitation(mesh_, settings.vapour_density_ratio)
    , turbulence(TurbulenceModel::create(mesh_, fluid, boundaries, settings, pattern))
  {
    boundaries.set_velocity_inlet_fluxes(state.flux);
    update_boundary_values();
  }

  Residuals SimplecSolver::Implementation::iterate(const IterationControl &control)
  {
    update_boundary_values();
    mesh.gradient(state.p, state.p_b, state.grad_p);
    momentum.hold_limiters(control.limiters_held_now());
    const MomentumEquation::Residuals m = momentum.assemble(state, boundaries, *turbulence, cavitation.convecting_flux(state.flux),
                                                            previous.dt > 0 ? &update_time_term() : nullptr);
    double imbalance = 0, throughput = 0;
    if (control.coupled())
      imbalance = coupled.solve(state, momentum, boundaries, cavitation, control.coupled_pressure_relaxation(), throughput);
    else
      {
        momentum.solve(state, control.iteration() == 1);
        update_boundary_values();
        std::vector<double> F = rhie_chow_fluxes(mesh, fluid.density, state, momentum.D(), boundaries);
        if (previous.dt > 0)
          add_time_step_correction(mesh, fluid.density, previous, momentum.D(), cavitation.mixture_ratios(), boundaries, F);
        throughput = continuity_reference(mesh, F, boundaries.velocity_inlet_inflow());
        imbalance = pressure.correct(F, state, momentum.D_simplec(), boundaries, cavitation, control.pressure_relaxation(),
                                     previous.dt > 0 ? &previous : nullptr);
        state.flux = std::move(F);
      }
    // the models after the new fluxes: cavitation, the pressure boundaries' inflow, turbulence
    if (cavitation.enabled())
      {
        cavitation.update_liquid_fraction(state.flux, &previous, fluid.density);
        cavitation.update_mixture_flux(state.flux);
      }
    boundaries.update_inflow_speeds(state.flux);
    Residuals r;
    if (turbulence->turbulent())
      {
        const TurbulenceResiduals t = turbulence->correct(state, mass_flux(), previous.dt > 0 ? &previous : nullptr);
        r.k = t.k, r.epsilon = t.epsilon;
      }
    const double scale = std::max(m.scale, vanishing);
    r.u = m.u / scale;
    r.v = m.v / scale;
    r.continuity = imbalance / std::max(throughput, vanishing);
    return r;
  }

  void SimplecSolver::Implementation::report_progress(const IterationControl &control, const Residuals &r) const
  {
    if (settings.report_interval == 0)
      return;
    const unsigned int it = control.iteration();
    if (control.report_due())
      {
        if (cavitation.enabled())
          std::fprintf(stderr, "  iteration %u: %zu cavitating cells\n", it, cavitation.n_cavitating());
        if (turbulence->turbulent())
          std::fprintf(stderr,
                       "  iteration %u: residuals u %.3e, v %.3e, continuity %.3e, k %.3e, epsilon %.3e; max mu_t/mu %.3g\n",
                       it, r.u, r.v, r.continuity, r.k, r.epsilon,
                       *std::max_element(turbulence->viscosity().begin(), turbulence->viscosity().end()) / fluid.viscosity);
        else
          std::fprintf(stderr, "  iteration %u: residuals u %.3e, v %.3e, continuity %.3e\n", it, r.u, r.v, r.continuity);
      }
    if (control.relaxation_lowered())
      std::fprintf(stderr, "  iteration %u: a cycle; pressure relaxation lowered to %.3g\n", it, control.pressure_relaxation());
    if (control.limiters_hold_started())
      std::fprintf(stderr, "  iteration %u: coupled iterations hover; convection limiters held from here\n", it);
    if (control.switched_to_coupled())
      std::fprintf(stderr, "  iteration %u: SIMPLEC stalled; coupled iterations from here\n", it);
    if (control.switched_back_to_simplec())
      std::fprintf(stderr, "  iteration %u: coupled iterations stalled too; SIMPLEC again from here\n", it);
  }

  // ---- public interface ----------------------------------------------------------------------

  SimplecSolver::SimplecSolver(const FvMesh &mesh, const FluidProperties &fluid,
                               const std::map<std::string, BoundaryCondition> &boundaries,
                               const FlowSolverParameters &settings)
    : impl(std::make_unique<Implementation>(mesh, fluid, boundaries, settings))
  {}

  SimplecSolver::~SimplecSolver() = default;

  SolveReport SimplecSolver::solve() { return solve_to(impl->settings.tolerance, true); }

  SolveReport SimplecSolver::solve_to(double tolerance, bool consult_monitor,
                                      const std::function<bool(const Residuals &)> &decided)
  {
    auto &d = *impl;
    d.forget_time_levels();
    // solve() goes back to SIMPLEC after stalled coupled iterations; solve_to() for a start state
    // (an intermediate pressure level, the liquid check) fails there as before: the flow stage was
    // measured unchanged with them so (doc/changes.md, issue 28: what stops Launder-Sharma's last flagged cases), not measured otherwise
    IterationControl control(d.settings, tolerance, consult_monitor ? &d.monitor : nullptr, d.turbulence->turbulent(),
                             consult_monitor);
    Residuals r;
    for (bool converged = false; !converged;)
      {
        const unsigned int it = control.next();
        try
          {
            r = d.iterate(control);
          }
        catch (const std::runtime_error &e) // a linear solve failed: the iteration is diverging
          {
            fail<std::runtime_error>(*this, d.mesh,
                                     "the solution diverged at iteration " + std::to_string(it) + " (" + e.what() + ")");
          }
        const IterationControl::Verdict verdict = control.judge(r, d);
        if (verdict != IterationControl::Verdict::diverged)
          d.report_progress(control, r);
        switch (verdict)
          {
            case IterationControl::Verdict::converged: converged = true; break;
            case IterationControl::Verdict::diverged: fail<std::runtime_error>(*this, d.mesh, control.reason());
            case IterationControl::Verdict::not_converged: fail<NotConverged>(*this, d.mesh, control.reason(), r);
            case IterationControl::Verdict::go_on: converged = decided && decided(r); break;
          }
      }
    return d.finish(control, r);
  }

  SolveReport SimplecSolver::Implementation::finish(const IterationControl &control, const Residuals &r)
  {
    update_boundary_values();
    state.grad_p = mesh.gradient(state.p, state.p_b);
    update_boundary_values();
    SolveReport report;
    report.iterations = control.iteration();
    report.residuals = r;
    report.pressure_relaxation = control.pressure_relaxation();
    report.cells_at_viscosity_limit = turbulence->turbulent() ? turbulence->cells_at_viscosity_limit() : 0;
    return report;
  }

  void SimplecSolver::set_boundary_pressure(const std::string &patch, double pressure)
  {
    impl->boundaries.set_pressure(patch, pressure);
    impl->update_boundary_values();
  }

  double SimplecSolver::boundary_pressure(const std::string &patch) const { return impl->boundaries.pressure(patch); }

  void SimplecSolver::set_turbulent_viscosity_limit(double ratio)
  {
    if (!(ratio > 0))
      throw std::invalid_argument("flow: turbulent viscosity limit " + format_number(ratio) + " must be > 0");
    impl->turbulence->set_viscosity_limit(ratio);
  }

  void SimplecSolver::set_cavitation_pressure(double p_cav)
  {
    if (!std::isfinite(p_cav))
      throw std::invalid_argument("flow: cavitation pressure " + format_number(p_cav) + " Pa");
    impl->cavitation.enable(p_cav);
    impl->cavitation.update_mixture_flux(impl->state.flux);
  }

  std::vector<double> SimplecSolver::liquid_fraction() const { return impl->cavitation.gamma; }

  void SimplecSolver::set_convergence_monitor(std::function<std::vector<double>()> monitor, unsigned int window,
                                              double relative_change)
  {
    impl->monitor = {std::move(monitor), std::max(1u, window), relative_change};
  }

  const std::vector<double> &SimplecSolver::velocity_x() const { return impl->state.u; }
  const std::vector<double> &SimplecSolver::velocity_y() const { return impl->state.v; }
  const std::vector<double> &SimplecSolver::pressure() const { return impl->state.p; }
  const std::vector<double> &SimplecSolver::turbulent_viscosity() const { return impl->turbulence->viscosity(); }
  const std::vector<double> &SimplecSolver::mass_flux() const { return impl->mass_flux(); }
  double SimplecSolver::boundary_pressure(std::size_t f) const { return impl->state.p_b[f]; }
  Vector2 SimplecSolver::boundary_velocity(std::size_t f) const { return Vector2(impl->state.u_b[f], impl->state.v_b[f]); }

  std::vector<double> SimplecSolver::wall_y_plus() const
  {
    return flow::wall_y_plus(impl->mesh, impl->state, impl->boundaries, impl->fluid);
  }
  double SimplecSolver::flow_rate(const std::string &patch) const
  {
    return flow::flow_rate(impl->mesh, impl->mass_flux(), impl->fluid.density, patch);
  }
  double SimplecSolver::mean_pressure(const std::string &patch) const
  {
    return flow::mean_pressure(impl->mesh, impl->state.p_b, patch);
  }
  double SimplecSolver::mean_total_pressure(const std::string &patch) const
  {
    return flow::mean_total_pressure(impl->mesh, impl->state, impl->mass_flux(), impl->fluid.density, patch);
  }
  double SimplecSolver::minimum_pressure() const { return flow::minimum_pressure(impl->mesh, impl->state); }
  double SimplecSolver::pressure_force(const std::string &patch, const Vector2 &direction, double p_reference) const
  {
    return flow::pressure_force(impl->mesh, impl->state.p_b, patch, direction, p_reference);
  }
  double SimplecSolver::throughput() const { return flow::throughput(impl->mesh, impl->mass_flux()); }
  double SimplecSolver::max_cell_imbalance() const
  {
    return flow::max_cell_imbalance(impl->mesh, impl->state.flux, impl->cavitation);
  }
  double SimplecSolver::net_imbalance() const { return flow::net_imbalance(impl->mesh, impl->mass_flux()); }

  void SimplecSolver::write_vtu(const std::string &filename) const
  {
    const auto &d = *impl;
    std::vector<std::pair<std::string, std::vector<double>>> extra{{"y_plus", wall_y_plus()}};
    for (const auto &[name, values] : d.turbulence->output_fields())
      extra.emplace_back(name, *values);
    if (d.cavitation.enabled())
      extra.emplace_back("liquid_fraction", d.cavitation.gamma);
    const FlowState &s = d.state;
    write_fv_vtu(filename, d.mesh, s.p, s.u, s.v, s.p_b, s.u_b, s.v_b, extra);
  }
} // namespace servodrift::flow
