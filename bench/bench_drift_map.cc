// Benchmark: one drift map of the default drift temperatures x 21 deviation angles (issue 2: under
// 1 s for 17 temperatures) on the reduced-order tables of RV-1 (every stage at the reduced order),
// and the system stage without plots and dynamics. Not a test: it prints wall times (minimum and
// median of several repetitions).
//   build/bench/bench_drift_map [repetitions]
#include "bench/benchmarks.h"
#include "bench/figures.h"
#include "bench/time_it.h"
#include "common/stage_output.h"
#include "common/sweep.h"
#include "flow/pilot/pilot_stage.h"
#include "magnetics/torque_motor_stage.h"
#include "structure/spring_tube_stage.h"
#include "system/drift_map.h"
#include "system/system_stage.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>

using namespace servodrift;

using servodrift::bench::time_it;

int servodrift::bench::bench_drift_map(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const int repetitions = argc > 1 ? std::atoi(argv[1]) : 5;
  const std::string dir = (std::filesystem::temp_directory_path() / "servodrift-bench").string();
  const ValveDescription valve = load_valve_description("", {"Output/Directory=" + dir, "Output/Progress=none",
                                                              "Output/Plots=false", "Pilot stage/Model level=reduced-order",
                                                              "Torque motor/Model level=reduced-order",
                                                              "Spring tube/Model level=reduced-order",
                                                              "Dynamics/Enabled=false"});
  const auto tables = time_it(repetitions, [&] {
    magnetics::run(valve);
    structure::run(valve);
    flow::run(valve);
  });
  const system::ValveModel model(valve, system::StageTables::read(tables_directory(valve), valve));
  const auto map = time_it(repetitions, [&] { system::compute_drift_map(model, OutputParameters::Progress::none); });
  const auto whole = time_it(repetitions, [&] { system::compute(valve, tables_directory(valve)); });
  if (mpi_rank() == 0)
    std::cout << "reduced-order tables (4 tables):          min " << tables.first << " s, median " << tables.second << " s\n"
              << "drift map " << valve.sweeps.drift_temperatures.size() << " x " << valve.sweeps.deviation_angles.size()
              << " (" << 2 * valve.sweeps.drift_temperatures.size() * valve.sweeps.deviation_angles.size()
              << " operating points): min " << map.first << " s, median " << map.second << " s\n"
              << "system stage without I/O (coefficients, drift map, E28): min " << whole.first << " s, median "
              << whole.second << " s\n"
              << "(" << repetitions << " repetitions, " << mpi_size() << " MPI rank(s))\n";
  const Figures figures(argc, argv);
  figures.record("one drift map, " + std::to_string(valve.sweeps.drift_temperatures.size()) + " temperatures x " +
                   std::to_string(valve.sweeps.deviation_angles.size()) + " angles, reduced-order tables",
                 "under 1 s", seconds(map.first));
  figures.record("the system stage without I/O (coefficients, drift map, E28)", "no target", seconds(whole.first));
  std::filesystem::remove_all(dir);
  return 0;
}
