// Benchmark of the tolerance study (issue 25) on RV-1's reduced-order tables, 8 toleranced
// quantities: the Monte Carlo of 10 000 valves x 9 temperatures (target: under 30 s on 2 cores) at
// 2 500, 5 000 and 10 000 valves (how it scales with the valves), and a Sobol' study at N = 4 096
// (40 960 valves, null-shift current only; target: under 3 min on 2 cores). Not a test: it prints
// wall times. Run it serially and under `mpirun -np 2' for the scaling with ranks.
//   build/bench/bench_tolerances [repetitions]
#include "bench/benchmarks.h"
#include "bench/figures.h"
#include "bench/time_it.h"
#include "common/stage_output.h"
#include "common/sweep.h"
#include "flow/pilot/pilot_stage.h"
#include "magnetics/torque_motor_stage.h"
#include "structure/spring_tube_stage.h"
#include "system/tolerance_study.h"

#include <deal.II/base/mpi.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>

using namespace servodrift;
using servodrift::bench::time_it;

int servodrift::bench::bench_tolerances(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const int repetitions = argc > 1 ? std::atoi(argv[1]) : 1;
  const std::string dir = (std::filesystem::temp_directory_path() / "servodrift-bench-tolerances").string();
  std::vector<std::string> settings = {
    "Output/Directory=" + dir, "Output/Progress=none", "Output/Plots=false",
    "Torque motor/Model level=reduced-order", "Spring tube/Model level=reduced-order",
    "Pilot stage/Model level=reduced-order", "Sweeps/Drift temperatures=40, 50, 60, 70, 80, 90, 100, 110, 120"};
  // 8 tolerances of the worked example (examples/rv1-tolerances.prm)
  for (const char *q : {"Left orifice diameter", "Right orifice diameter", "Left nozzle diameter", "Right nozzle diameter",
                        "Left null gap", "Right null gap"})
    {
      settings.push_back(std::string("Tolerances/") + q + "/Distribution=normal");
      settings.push_back(std::string("Tolerances/") + q + "/Standard deviation=1e-6");
    }
  for (const char *q : {"Spring tube rest angle", "Magnetic null"})
    {
      settings.push_back(std::string("Tolerances/") + q + "/Distribution=normal");
      settings.push_back(std::string("Tolerances/") + q + "/Standard deviation=1.745e-4");
    }
  ValveDescription valve = load_valve_description("", settings);
  magnetics::run(valve);
  structure::run(valve);
  flow::run(valve);
  const system::ValveModel model(valve, system::StageTables::read(tables_directory(valve), valve));
  valve.tolerances.sobol_base_samples = 0;
  const Figures figures(argc, argv);
  const std::string ranks = std::to_string(mpi_size()) + " rank" + (mpi_size() > 1 ? "s" : "");
  for (unsigned int samples : {2500u, 5000u, 10000u})
    {
      ValveDescription v = valve;
      v.tolerances.samples = samples;
      const system::ValveModel m(v, system::StageTables::read(tables_directory(v), v));
      const auto t = time_it(repetitions, [&] { system::compute_tolerances(m, OutputParameters::Progress::none); });
      if (mpi_rank() == 0)
        std::cout << "Monte Carlo " << samples << " valves x 9 temperatures: min " << t.first << " s, median "
                  << t.second << " s (" << 1e3 * t.first / samples << " ms per valve)" << std::endl;
      figures.record("Monte Carlo of " + std::to_string(samples) + " valves x 9 temperatures, reduced order",
                     samples == 10000 ? "under 30 s on 2 cores" : "no target", seconds(t.first) + " on " + ranks);
    }
  ValveDescription v = valve;
  v.tolerances.samples = 1;
  v.tolerances.sobol_base_samples = 4096;
  const system::ValveModel m(v, system::StageTables::read(tables_directory(v), v));
  const auto t = time_it(repetitions, [&] { system::compute_tolerances(m, OutputParameters::Progress::none); });
  if (mpi_rank() == 0)
    std::cout << "Sobol' study of 8 tolerances, N = 4096 (40 960 valves x 9 temperatures): min " << t.first
              << " s, median " << t.second << " s\n(" << repetitions << " repetitions, " << mpi_size()
              << " MPI rank(s))\n";
  figures.record("Sobol' study of 8 tolerances, N = 4096 (40 960 valves x 9 temperatures)", "under 3 min on 2 cores",
                 seconds(t.first) + " on " + ranks);
  if (mpi_rank() == 0) // every rank ends here; one removes what they shared
    std::filesystem::remove_all(dir);
  return 0;
}
