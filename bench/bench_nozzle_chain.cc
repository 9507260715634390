// One temperature's nozzle-flapper chain as the flow stage runs it (flow/pilot/pilot_field_stage.cc, in
// its gap order: the null gap, the smaller gaps downwards, then the larger ones upwards, each gap at
// every nozzle pressure difference), up to and including the gap asked for. One line per case:
// iterations, flag, C_dn, the flapper force and the wall time, the numbers of
// flow/nozzle_flapper_cases.csv. Reproduces one case of the sweep with the path that led to it in
// about a minute instead of a flow stage (RV-1 at 100 degC up to 20 um: 36 s on one core,
// 2026-11-28). Not a test.
//   OMP_THREAD_LIMIT=1 build/bench/bench_nozzle_chain <temperature [degC]> <gap [um]> [parameter=value ...]
// (extra arguments are `--set' entries, e.g. 'Flow solver/Report interval=50' for the residuals)
#include "bench/benchmarks.h"
#include "common/valve_description.h"
#include "flow/pilot/pilot_field_cases.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

using namespace servodrift;
using namespace servodrift::flow;

int servodrift::bench::bench_nozzle_chain(int argc, char **argv)
{
  if (argc < 3)
    {
      std::fprintf(stderr, "usage: bench_nozzle_chain <temperature [degC]> <gap [um]> [parameter=value ...]\n");
      return 1;
    }
  const double T = std::atof(argv[1]), last_gap = std::atof(argv[2]) * 1e-6;
  std::vector<std::string> settings{"Output/Progress=none"};
  for (int a = 3; a < argc; ++a)
    settings.emplace_back(argv[a]);
  const ValveDescription valve = load_valve_description("", settings);
  const auto gaps = scaled(valve.sweeps.field_gap_fractions, valve.pilot.null_gap);
  const auto dps = scaled(valve.sweeps.field_nozzle_pressure_fractions, span(valve));
  std::printf("RV-1 nozzle-flapper chain at %g degC, in the stage's gap order up to %g um\n", T, last_gap * 1e6);
  std::printf("%8s %10s %10s %6s %12s %12s %9s\n", "gap [um]", "dp [MPa]", "iterations", "flag", "C_dn", "F [N]",
              "wall [s]");
  Chain chain(valve, PilotGeometry::nozzle_flapper, T);
  std::vector<std::optional<FlowFields>> first(gaps.size()); // each gap's fields at its first dp
  for (const auto &[k, from] : gap_order(valve.sweeps.field_gap_fractions))
    {
      for (std::size_t j = 0; j < dps.size(); ++j)
        {
          const auto r = chain.solve(gaps[k], dps[j], j == 0 && from >= 0 ? first[from] : std::nullopt);
          std::printf("%8.3g %10.4g %10.0f %6.0f %12.9f %12.9f %9.2f\n", gaps[k] * 1e6, dps[j] / 1e6,
                      r[case_record::iterations], r[case_record::flag], r[case_record::discharge_coefficient],
                      r[case_record::flapper_force], r[case_record::wall_time]);
          std::fflush(stdout);
          if (j == 0)
            first[k] = chain.last_fields();
        }
      if (std::abs(gaps[k] - last_gap) <= 1e-3 * last_gap)
        return 0;
    }
  std::fprintf(stderr, "bench_nozzle_chain: no gap of `Sweeps/Field gap fractions' is %g um\n", last_gap * 1e6);
  return 1;
}
