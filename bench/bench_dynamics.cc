// Benchmark of the dynamics (issue 23) on RV-1's reduced-order tables, 9 temperatures (40..120 degC):
//   1. the linearised frequency response, 9 temperatures x 200 frequencies (target: under 1 s);
//   2. one nonlinear step response 0 -> rated current to settling, at 40 degC, the slowest (target:
//      under 0.5 s on one core);
//   3. the nonlinear sine check, 10 frequencies x 9 temperatures, each halved to the linear limit, shared over the MPI ranks by
//      run_sweep (target: under 30 s on 2 cores: mpirun -np 2);
//   4. the whole dynamics stage (every analysis of `servodrift run'), for the record.
// Not a test: it prints wall times (minimum and median of the repetitions).
//   build/bench/bench_dynamics [repetitions]          (or under mpirun -np 2)
#include "bench/benchmarks.h"
#include "bench/figures.h"
#include "bench/time_it.h"
#include "common/stage_output.h"
#include "common/sweep.h"
#include "flow/pilot/pilot_stage.h"
#include "magnetics/torque_motor_stage.h"
#include "structure/spring_tube_stage.h"
#include "system/dynamics.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>

using namespace servodrift;
using namespace servodrift::system;

using servodrift::bench::time_it;

int servodrift::bench::bench_dynamics(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const int repetitions = argc > 1 ? std::atoi(argv[1]) : 3;
  const std::string dir = (std::filesystem::temp_directory_path() / "servodrift-bench-dynamics").string();
  const ValveDescription valve = load_valve_description(
    "", {"Output/Directory=" + dir, "Output/Progress=none", "Output/Plots=false", "Pilot stage/Model level=reduced-order",
         "Torque motor/Model level=reduced-order", "Spring tube/Model level=reduced-order",
         "Sweeps/Drift temperatures=40, 50, 60, 70, 80, 90, 100, 110, 120"});
  magnetics::run(valve); // every stage runs on every rank (sweeps are collective); rank 0 writes
  structure::run(valve);
  flow::run(valve);
  const ValveModel model(valve, StageTables::read(tables_directory(valve), valve));
  const auto &p = valve.dynamics;
  const double rated = valve.operating.rated_current, bias = p.bias * rated, R0 = amplifier_resistance(valve);
  const auto &temperatures = valve.sweeps.drift_temperatures;

  const auto linear = time_it(repetitions, [&] {
    for (double T : temperatures)
      {
        const ValveDynamics d(model.equations(T), R0, rated);
        const Linearisation l = linearise(d, model.solve(d.equations(), bias).state(), bias);
        frequency_response(l, Output::brake_pressure, p.minimum_frequency, p.maximum_frequency, 200);
      }
  });
  long steps = 0;
  const auto step = time_it(repetitions, [&] {
    const ValveDynamics d(model.equations(40), R0, rated);
    steps = step_response(model, d, 0.0, rated, p, 600).statistics.steps;
  });
  std::size_t responses = 0;
  const auto sines = time_it(repetitions, [&] {
    const CaseRows rows = run_sweep(
      "sine check", temperatures.size() * p.sine_frequencies.size(),
      [&](std::size_t c) {
        const double T = temperatures[c / p.sine_frequencies.size()], f = p.sine_frequencies[c % p.sine_frequencies.size()];
        const ValveDynamics d(model.equations(T), R0, rated);
        const OperatingPoint point = model.solve(d.equations(), bias);
        const Linearisation l = linearise(d, point.state(), bias);
        const SineCheck check = sine_check(d, l, point.state(), bias, f, p.sine_check_amplitude * rated, p);
        return CaseRows{{double(check.halvings.size())}};
      },
      OutputParameters::Progress::none);
    responses = 0;
    for (const auto &row : rows)
      responses += std::size_t(row[0]);
  });
  const auto whole = time_it(repetitions, [&] { compute_dynamics(model, OutputParameters::Progress::none); });
  if (mpi_rank() == 0)
    std::cout << "linearised frequency response, " << temperatures.size() << " temperatures x 200 frequencies: min "
              << linear.first << " s, median " << linear.second << " s\n"
              << "step response 0 -> rated at 40 degC (" << steps << " steps): min " << step.first << " s, median "
              << step.second << " s\n"
              << "sine check, " << p.sine_frequencies.size() << " frequencies x " << temperatures.size()
              << " temperatures, halved to the linear limit (" << responses << " sine responses): min " << sines.first
              << " s, median " << sines.second << " s\n"
              << "whole dynamics stage (" << temperatures.size() << " temperatures): min " << whole.first
              << " s, median " << whole.second << " s\n"
              << "(" << repetitions << " repetitions, " << mpi_size() << " MPI rank(s))\n";
  const Figures figures(argc, argv);
  figures.record("linearised frequency response, " + std::to_string(temperatures.size()) +
                   " temperatures x 200 frequencies",
                 "under 1 s", seconds(linear.first));
  figures.record("one nonlinear step response 0 -> rated at 40 degC, to settling", "under 0.5 s on one core",
                 seconds(step.first));
  figures.record("sine check, " + std::to_string(p.sine_frequencies.size()) + " frequencies x " +
                   std::to_string(temperatures.size()) + " temperatures, halved to the linear limit",
                 "under 30 s on 2 cores", seconds(sines.first));
  figures.record("whole dynamics stage, " + std::to_string(temperatures.size()) + " temperatures", "no target",
                 seconds(whole.first));
  if (mpi_rank() == 0)
    std::filesystem::remove_all(dir);
  return 0;
}
