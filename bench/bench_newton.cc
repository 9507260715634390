// Newton-PTC against SIMPLEC on single pilot-stage cases (issue 63): a laminar, single-phase nozzle or
// orifice case of RV-1 is solved by SIMPLEC at a neighbouring pressure difference (the continuation
// neighbour: dp / ratio), then at dp both by SIMPLEC (the flow stage's path) and by Newton-PTC from
// that neighbour, and the two answers and costs are printed: steps, Jacobians, colours, the seconds
// of residuals, Jacobians and factorisations, the flow rate and the largest field differences. Last,
// Newton-PTC from rest (fields zero, dp applied at once) at three first CFL numbers.
//   OMP_THREAD_LIMIT=1 build/bench/bench_newton [nozzle|orifice] [temperature degC] [dp Pa] [ratio] [CFL_0]
#include "bench/benchmarks.h"
#include "common/valve_description.h"
#include "flow/pilot/pilot_field.h"
#include "flow/fv/simplec.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace servodrift;
using namespace servodrift::flow;

namespace
{
  double seconds_since(std::chrono::steady_clock::time_point t0)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
} // namespace

int servodrift::bench::bench_newton(int argc, char **argv)
{
  const std::string which = argc > 1 ? argv[1] : "nozzle";
  const double T = argc > 2 ? std::atof(argv[2]) : 40;
  ValveDescription valve = load_valve_description("", {});
  const double dp = argc > 3 ? std::atof(argv[3]) : (which == "nozzle" ? 2e6 : 5e6);
  const double ratio = argc > 4 ? std::atof(argv[4]) : 1.25;
  valve.pilot.field_solution.cavitation = false;
  valve.pilot.field_solution.fixed_orifice_flow_model = valve.pilot.field_solution.nozzle_flow_model = PilotFieldSolutionParameters::FlowModel::laminar;
  const PilotGeometry geometry = which == "nozzle" ? PilotGeometry::nozzle_flapper : PilotGeometry::fixed_orifice;
  const PilotFieldCase c = pilot_field_case(valve, T);
  const double gap = valve.pilot.null_gap;
  const PilotFieldSettings case_settings = pilot_field_settings(valve);

  PilotField neighbour(case_settings, geometry, c, gap);
  auto t0 = std::chrono::steady_clock::now();
  neighbour.solve(dp / ratio);
  std::printf("%s, %g degC, laminar, single phase, %zu cells: neighbour at %.4g Pa by SIMPLEC in %.2f s\n",
              which.c_str(), T, neighbour.n_cells(), dp / ratio, seconds_since(t0));

  PilotField simplec(case_settings, geometry, c, gap), newton(case_settings, geometry, c, gap);
  simplec.initialize_from(neighbour);
  newton.initialize_from(neighbour);
  t0 = std::chrono::steady_clock::now();
  const PilotFieldResult rs = simplec.solve(dp);
  const double simplec_seconds = seconds_since(t0);
  std::printf("SIMPLEC from the neighbour: %u iterations, %.2f s, Q %.9e m^3/s\n", rs.iterations, simplec_seconds,
              simplec.solver().flow_rate("outlet"));

  SimplecSolver &solver = newton.solver();
  t0 = std::chrono::steady_clock::now();
  solver.scale_pressure_level(ratio);
  PtcSettings settings;
  if (argc > 5)
    settings.initial_cfl = std::atof(argv[5]);
  const PtcReport r = solver.solve_newton(settings);
  const double newton_seconds = seconds_since(t0);
  std::printf("Newton-PTC from the neighbour (CFL_0 %g): %s, %u steps, %u Jacobians of %u colours, %zu entries (%zu "
              "unknowns), %.2f s (residuals %.2f s in %u, "
              "Jacobians %.2f s, LU %.2f s), Q %.9e m^3/s\n  norm",
              settings.initial_cfl, to_string(r.outcome).c_str(), r.steps, r.jacobians, r.colours, r.jacobian_entries,
              r.unknowns, newton_seconds, r.residual_seconds, r.residual_evaluations, r.jacobian_seconds,
              r.factorisation_seconds, solver.flow_rate("outlet"));
  for (double h : r.history)
    std::printf(" %.1e", h);
  if (r.limiter_held)
    std::printf(" (limiter held near the solution)");
  double speed = 0, du = 0, dpmax = 0, prange = 0;
  const SimplecSolver &a = simplec.solver();
  for (std::size_t k = 0; k < newton.n_cells(); ++k)
    {
      speed = std::max(speed, std::hypot(a.velocity_x()[k], a.velocity_y()[k]));
      du = std::max({du, std::abs(a.velocity_x()[k] - solver.velocity_x()[k]),
                     std::abs(a.velocity_y()[k] - solver.velocity_y()[k])});
      dpmax = std::max(dpmax, std::abs(a.pressure()[k] - solver.pressure()[k]));
      prange = std::max(prange, std::abs(a.pressure()[k]));
    }
  std::printf(
      "\n  Newton against SIMPLEC: velocity %.2e of the largest, pressure %.2e of the largest, Q %.2e relative\n",
      du / speed, dpmax / prange, solver.flow_rate("outlet") / a.flow_rate("outlet") - 1);

  // from rest: the fields zero, the pressure difference applied at once (PTC's time-like path)
  for (const double cfl : {1e-2, 1.0, 100.0})
    {
      PilotField rest(case_settings, geometry, c, gap);
      rest.solver().set_boundary_pressure("inlet", dp);
      PtcSettings s = settings;
      s.initial_cfl = cfl;
      t0 = std::chrono::steady_clock::now();
      const PtcReport q = rest.solver().solve_newton(s);
      std::printf("Newton-PTC from rest (CFL_0 %g): %s, %u steps, %u Jacobians, %.2f s, norm %.1e, Q %.2e relative to "
                  "SIMPLEC's\n",
                  cfl, to_string(q.outcome).c_str(), q.steps, q.jacobians, seconds_since(t0), q.norm,
                  rest.solver().flow_rate("outlet") / a.flow_rate("outlet") - 1);
    }
  return 0;
}
