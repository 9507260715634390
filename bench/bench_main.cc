// One program for the benchmark drivers (bench/benchmarks.h): it runs the driver named by the link
// it was started through (build/bench/bench_flow ...) or by its first argument
// (build/bench/servodrift_bench bench_flow ...). `servodrift_bench' alone lists them.
#include "bench/benchmarks.h"
#include "common/sweep.h"

#include <cstdio>
#include <cstring>
#include <string>

namespace
{
  struct Driver
  {
    const char *name;
    int (*run)(int, char **);
  };

  constexpr Driver drivers[] = {
    {"bench_bore_sensitivity", servodrift::bench::bench_bore_sensitivity},
    {"bench_calibration", servodrift::bench::bench_calibration},
    {"bench_cold_start", servodrift::bench::bench_cold_start},
    {"bench_drift_map", servodrift::bench::bench_drift_map},
    {"bench_dynamics", servodrift::bench::bench_dynamics},
    {"bench_flow", servodrift::bench::bench_flow},
    {"bench_magnetics", servodrift::bench::bench_magnetics},
    {"bench_mesh_convergence", servodrift::bench::bench_mesh_convergence},
    {"bench_narrow_gap_paths", servodrift::bench::bench_narrow_gap_paths},
    {"bench_newton", servodrift::bench::bench_newton},
    {"bench_nozzle_chain", servodrift::bench::bench_nozzle_chain},
    {"bench_orifice_march", servodrift::bench::bench_orifice_march},
    {"bench_orifice_reynolds", servodrift::bench::bench_orifice_reynolds},
    {"bench_pilot_field", servodrift::bench::bench_pilot_field},
    {"bench_structure", servodrift::bench::bench_structure},
    {"bench_tolerances", servodrift::bench::bench_tolerances},
  };

  const Driver *find(const std::string &name)
  {
    for (const Driver &d : drivers)
      if (name == d.name)
        return &d;
    return nullptr;
  }
} // namespace

int main(int argc, char **argv)
{
  servodrift::one_thread_per_process();
  const std::string program = argv[0];
  const std::string invoked = program.substr(program.find_last_of('/') + 1);
  if (const Driver *d = find(invoked))
    return d->run(argc, argv);
  if (argc > 1)
    if (const Driver *d = find(argv[1]))
      return d->run(argc - 1, argv + 1); // the driver sees its own name as argv[0]
  if (argc > 1 && std::strcmp(argv[1], "--help") != 0 && std::strcmp(argv[1], "-h") != 0)
    std::fprintf(stderr, "servodrift_bench: no benchmark named '%s'\n", argv[1]);
  std::printf("usage: servodrift_bench <benchmark> [arguments]  (or build/bench/<benchmark> [arguments])\n"
              "benchmarks (bench/<benchmark>.cc says what each measures and its arguments):\n");
  for (const Driver &d : drivers)
    std::printf("  %s\n", d.name);
  return argc > 1 && std::strcmp(argv[1], "--help") != 0 && std::strcmp(argv[1], "-h") != 0 ? 2 : 0;
}
