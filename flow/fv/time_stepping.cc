// SimplecSolver: time stepping (BDF2, its first step implicit Euler) for flows without a steady
// solution, whose time average then stands for them (doc/method.md, "Time stepping and time
// averages"). Each step is the steady iteration with the time term rho_m V du/dt in the momentum
// equations (momentum_equation.h), the old levels' share of the Rhie-Chow fluxes (Choi's correction,
// rhie_chow.h) and the change of a cavitating cell's mass in its liquid-fraction balance
// (cavitation_model.h); the pressure correction is unchanged (the liquid is incompressible, a
// cavitating cell holds p_cav). Verified in tests/verification/flow_time_stepping_test.cc and
// pilot_field_time_average_test.cc.
#include "flow/fv/simplec_implementation.h"

#include "common/error.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace servodrift::flow
{
  const MomentumEquation::TimeTerm &SimplecSolver::Implementation::update_time_term()
  {
    const std::size_t n = mesh.n_cells();
    time_term.diagonal.resize(n);
    previous.storage_rate.resize(n);
    for (auto &source : time_term.source)
      source.resize(n);
    for (std::size_t c = 0; c < n; ++c)
      {
        // rho_m du/dt, the current mixture's density on every level: a cell that changes phase within a
        // step changes its density a thousandfold, and the conservative d(rho_m u)/dt then turned the
        // mass the pressure correction does not see (a liquid cell has no storage) into momentum
        // (RV-1's steady cavitating null diverged within five steps)
        const double per_step = fluid.density * cavitation.mixture_ratio(c) * mesh.cell_volume[c] / previous.dt;
        previous.storage_rate[c] = per_step;
        time_term.diagonal[c] = per_step * previous.new_weight();
        time_term.source[0][c] = per_step * previous.old_velocity(0, c);
        time_term.source[1][c] = per_step * previous.old_velocity(1, c);
      }
    return time_term;
  }

  SolveReport SimplecSolver::advance(double dt, unsigned int max_iterations, double tolerance)
  {
    auto &d = *impl;
    if (!(dt > 0) || !std::isfinite(dt) || max_iterations == 0)
      throw std::invalid_argument("flow: time step " + format_number(dt) + " s must be > 0, with at least one iteration");
    // BDF2 from the second step of a run at constant dt (the fields unchanged in between: every
    // other change of the state forgets the levels), implicit Euler otherwise
    if (dt == d.time_step && !d.previous.last.u.empty())
      d.previous.before = std::move(d.previous.last);
    else
      d.previous.before = {};
    d.previous.dt = d.time_step = dt;
    d.previous.last.u = d.state.u, d.previous.last.v = d.state.v, d.previous.last.flux = d.state.flux;
    d.previous.last.turbulence = d.turbulence->transported_fields();
    d.previous.last.mixture.resize(d.mesh.n_cells());
    for (std::size_t c = 0; c < d.mesh.n_cells(); ++c)
      d.previous.last.mixture[c] = d.cavitation.mixture_ratio(c);
    // the steady iteration's tests for a cycle, a stall and acceleration belong to a fixed point,
    // not to a time step: its iterations only converge the step's implicit equations
    FlowSolverParameters inner = d.settings;
    inner.coupling = FlowSolverParameters::Coupling::simplec;
    inner.acceleration_depth = 0;
    inner.cycle_window = inner.stall_window = 0;
    inner.max_iterations = max_iterations;
    IterationControl control(inner, tolerance, nullptr, false);
    // no under-relaxation of momentum within a step: the time term keeps its equations diagonally
    // dominant, and with alpha_u < 1 the Rhie-Chow fluxes of a flow at rest in time would keep a
    // dependence on dt (D = alpha_u V/(a_P + rho V/dt) against Choi's correction)
    const double steady_relaxation = d.momentum.relaxation();
    d.momentum.set_relaxation(1);
    struct Restore
    {
      MomentumEquation &momentum;
      double alpha;
      ~Restore() { momentum.set_relaxation(alpha); }
    } restore{d.momentum, steady_relaxation};
    Residuals r;
    bool converged = false;
    for (bool done = false; !done;)
      {
        const unsigned int it = control.next();
        try
          {
            r = d.iterate(control);
          }
        catch (const std::runtime_error &e)
          {
            d.forget_time_levels();
            throw std::runtime_error("flow: " + d.mesh.source + ": the time step diverged at iteration " +
                                     std::to_string(it) + " (" + e.what() + ")");
          }
        switch (control.judge(r, d))
          {
            case IterationControl::Verdict::go_on: break;
            case IterationControl::Verdict::diverged:
              d.forget_time_levels();
              throw std::runtime_error("flow: " + d.mesh.source + ": time step: " + control.reason());
            case IterationControl::Verdict::converged: converged = done = true; break;
            default: done = true; // the step's iterations used up
          }
      }
    d.previous.dt = 0; // steady again unless the next step is called
    SolveReport report = d.finish(control, r);
    report.converged = converged;
    return report;
  }

  double SimplecSolver::courant_time_step(double courant) const
  {
    const auto &d = *impl;
    const std::vector<double> &F = d.mass_flux();
    double rate = 0; // the largest sum|F|/(2 rho_m V) [1/s]
    for (std::size_t c = 0; c < d.mesh.n_cells(); ++c)
      {
        double sum = 0;
        for (unsigned int f : d.mesh.cell_faces[c])
          sum += std::abs(F[f]);
        rate = std::max(rate, sum / (2 * d.fluid.density * d.cavitation.mixture_ratio(c) * d.mesh.cell_volume[c]));
      }
    if (!(rate > 0))
      throw std::invalid_argument("flow: " + d.mesh.source + ": no flow to set a time step by");
    return courant / rate;
  }
} // namespace servodrift::flow
