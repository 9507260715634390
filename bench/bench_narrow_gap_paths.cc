// Path dependence of a narrow-gap nozzle case (issue 28, item 6; doc/validation.md, "Robustness"):
// one case of RV-1's default sweep solved on three paths with the default flow model, each in a
// fresh continuation chain (flow/pilot/pilot_field_cases.h's Chain):
//   rest       the case alone: pressure continuation from rest up to its pressure difference;
//   neighbour  the flow stage's path: the next larger gap at the same pressure difference first,
//              then this gap from its fields;
//   descending the case at the sweep's largest pressure difference first, then down to its own.
// Prints per path C_d, the flapper force, the cells that cavitate and the lowest absolute
// pressure, then marches each path's state in time (`Pilot stage/Time average/Steps' steps) to see
// whether it holds. Converged states that differ by more than the solver's tolerance are
// distinct solutions of the same discrete equations; before PilotField's liquid check the paths
// from the wider gap and from above kept cavities that collapse when marched (doc/validation.md,
// "Robustness"). Not a test (tens of seconds).
//   OMP_THREAD_LIMIT=1 build/bench/bench_narrow_gap_paths [T degC] [gap m] [dp Pa] [neighbour gap m] [parameter=value ...]
// (defaults 50 degC, 10e-6 m, 3.09e6 Pa, 20e-6 m)
#include "bench/benchmarks.h"
#include "common/valve_description.h"
#include "flow/pilot/pilot_field.h"
#include "flow/pilot/pilot_field_cases.h"
#include "flow/pilot/pilot_field_time_average.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace servodrift;
using namespace servodrift::flow;

namespace
{
  void print(const char *path, const std::vector<double> &r, const std::optional<FlowFields> &fields)
  {
    using namespace case_record;
    const std::size_t cavitating =
      fields ? static_cast<std::size_t>(std::count(fields->cavitating.begin(), fields->cavitating.end(), 1)) : 0;
    std::printf("%-10s flag %.0f, %5.0f iterations, C_d %.5f, F %.5f N, %4zu cavitating cells, lowest pressure %.4g Pa\n",
                path, r[flag], r[iterations], r[discharge_coefficient], r[flapper_force], cavitating,
                r[minimum_absolute_pressure]);
    std::fflush(stdout);
  }
  /// The state marched in time (`Pilot stage/Time average/Steps' steps of `Time average/
  /// Courant number'): whether it holds (a stable steady state) or moves to another.
  void march(const char *path, const ValveDescription &valve, double T, double h, double dp, const FlowFields &start)
  {
    PilotField field(pilot_field_settings(valve), PilotGeometry::nozzle_flapper, pilot_field_case(valve, T), h);
    field.set_fields(start);
    const double dt = field.courant_time_step(valve.pilot.time_average.courant_number);
    PilotFieldResult r;
    unsigned int capped = 0;
    const unsigned int steps = valve.pilot.time_average.steps, tenth = std::max(1u, steps / 10);
    for (unsigned int step = 1; step <= steps; ++step)
      {
        r = field.advance(dp, dt, valve.pilot.time_average.step_iterations, step_tolerance);
        capped += !r.step_converged;
        if (step % tenth == 0 && step < steps) // the trajectory: whether and when a cavity collapses
          std::printf("%-10s   step %5u, t %.3g us: C_d %.5f, F %.5f N, cavitating %d, lowest pressure %.4g Pa\n", path,
                      step, step * dt * 1e6, r.discharge_coefficient, r.flapper_force, int(r.cavitating),
                      r.minimum_absolute_pressure);
      }
    const FlowFields f = field.fields();
    const std::size_t cavitating = static_cast<std::size_t>(std::count(f.cavitating.begin(), f.cavitating.end(), 1));
    std::printf("%-10s marched %u steps of %.3g s (%u capped): C_d %.5f, F %.5f N, %4zu cavitating cells, lowest "
                "pressure %.4g Pa\n",
                path, valve.pilot.time_average.steps, dt, capped, r.discharge_coefficient, r.flapper_force, cavitating,
                r.minimum_absolute_pressure);
    std::fflush(stdout);
  }
} // namespace

int servodrift::bench::bench_narrow_gap_paths(int argc, char **argv)
{
  const double T = argc > 1 ? std::atof(argv[1]) : 50, h = argc > 2 ? std::atof(argv[2]) : 10e-6;
  const double dp = argc > 3 ? std::atof(argv[3]) : 3.09e6, neighbour = argc > 4 ? std::atof(argv[4]) : 20e-6;
  std::vector<std::string> settings{"Output/Progress=none", "Output/Flow fields=none"};
  for (int a = 5; a < argc; ++a)
    settings.push_back(argv[a]);
  ValveDescription valve;
  try
    {
      valve = load_valve_description("", settings);
    }
  catch (const std::exception &e)
    {
      std::fprintf(stderr, "bench_narrow_gap_paths: %s\n", e.what());
      return 2;
    }
  const std::vector<double> dps = scaled(valve.sweeps.field_nozzle_pressure_fractions, span(valve));
  std::printf("RV-1, %g degC, gap %g m, dp %g Pa, default flow model, cavitation %s\n", T, h, dp,
              valve.pilot.field_solution.cavitation ? "on" : "off");
  {
    Chain chain(valve, PilotGeometry::nozzle_flapper, T);
    const auto r = chain.solve(h, dp);
    print("rest", r, chain.last_fields());
    if (chain.last_fields())
      march("rest", valve, T, h, dp, *chain.last_fields());
  }
  {
    Chain chain(valve, PilotGeometry::nozzle_flapper, T);
    chain.solve(neighbour, dp);
    const auto r = chain.solve(h, dp, chain.last_fields());
    print("neighbour", r, chain.last_fields());
    if (chain.last_fields())
      march("neighbour", valve, T, h, dp, *chain.last_fields());
  }
  {
    Chain chain(valve, PilotGeometry::nozzle_flapper, T);
    std::vector<double> r;
    for (auto level = dps.rbegin(); level != dps.rend(); ++level)
      if (*level > dp)
        chain.solve(h, *level);
    r = chain.solve(h, dp);
    print("descending", r, chain.last_fields());
    if (chain.last_fields())
      march("descending", valve, T, h, dp, *chain.last_fields());
  }
  return 0;
}
