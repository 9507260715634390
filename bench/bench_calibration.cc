// Benchmark of the calibration (issue 26): 4 free parameters fitted to 20 measured values (the
// null-shift current and the brake pressure at the rated current at 10 temperatures, made by the
// model from known parameters with Gaussian noise), from RV-1's reduced-order tables, one core.
// Target: under 5 s. Not a test: it prints wall times and what the fit found.
//   build/bench/bench_calibration [repetitions]
#include "bench/benchmarks.h"
#include "bench/figures.h"
#include "bench/time_it.h"
#include "common/stage_output.h"
#include "flow/pilot/pilot_stage.h"
#include "magnetics/torque_motor_stage.h"
#include "structure/spring_tube_stage.h"
#include "system/calibration.h"
#include "system/calibration_model.h"

#include <deal.II/base/mpi.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <random>

using namespace servodrift;
using servodrift::bench::time_it;

int servodrift::bench::bench_calibration(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const int repetitions = argc > 1 ? std::atoi(argv[1]) : 3;
  const std::string dir = (std::filesystem::temp_directory_path() / "servodrift-bench-calibration").string();
  const std::vector<std::string> overrides = {
    "Output/Progress=none", "Output/Plots=false", "Torque motor/Model level=reduced-order",
    "Spring tube/Model level=reduced-order", "Pilot stage/Model level=reduced-order"};
  std::vector<std::string> with_dir = overrides;
  with_dir.push_back("Output/Directory=" + dir);
  const ValveDescription valve = load_valve_description("", with_dir);
  magnetics::run(valve);
  structure::run(valve);
  flow::run(valve);
  const system::StageTables tables = system::StageTables::read(tables_directory(valve), valve);

  const std::vector<std::string> free = {"Offsets/Magnetic null", "Asymmetry/Left orifice diameter deviation",
                                         "Asymmetry/Right nozzle diameter deviation", "Asymmetry/Left null gap deviation"};
  const std::vector<double> truth = {0.02, 1.5e-6, -1e-6, 0.5e-6};
  std::vector<system::Measurement> points;
  for (int k = 0; k < 10; ++k)
    {
      const double T = 48 + 8 * k;
      points.push_back({0, T, 0.0, system::MeasuredQuantity::null_shift_current, 0.0, 1e-6});
      points.push_back({0, T, 0.02, system::MeasuredQuantity::brake_pressure, 0.0, 1e4});
    }
  std::vector<system::FreeParameter> parameters;
  for (const auto &f : free)
    parameters.push_back({f, "", 0, -1, 1});
  const system::CalibrationRequest model_request{"", free, "", overrides};
  const std::vector<double> exact = system::CalibrationModel(model_request, parameters, tables).predict(truth, points);
  std::mt19937_64 random(1);
  std::normal_distribution<double> gauss;
  const std::string file = dir + "/measured.csv";
  {
    std::ofstream out(file);
    out << "temperature[degC],current[A],null_shift_current[A],null_shift_current_sd[A],brake_pressure[Pa],brake_pressure_sd[Pa]\n"
        << std::setprecision(17);
    for (std::size_t k = 0; k < points.size(); ++k)
      {
        const double y = exact[k] + points[k].standard_deviation * gauss(random);
        out << points[k].temperature << "," << points[k].current << ",";
        if (points[k].quantity == system::MeasuredQuantity::null_shift_current)
          out << y << "," << points[k].standard_deviation << ",,\n";
        else
          out << ",," << y << "," << points[k].standard_deviation << "\n";
      }
  }
  const system::CalibrationRequest request{file, free, "", overrides};
  system::CalibrationResults result;
  const auto t = time_it(repetitions, [&] {
    const auto setup = system::prepare_calibration(request, tables);
    result = system::calibrate(request, setup, tables);
  });
  std::cout << "calibration, 4 free parameters, 20 measured values: min " << t.first << " s, median " << t.second
            << " s (" << result.iterations << " iterations, " << repetitions << " repetitions, one core)\n";
  for (std::size_t j = 0; j < free.size(); ++j)
    std::cout << "  " << free[j] << ": truth " << truth[j] << ", estimate " << result.estimates[j] << " +- "
              << (result.standard_errors[j] ? std::to_string(*result.standard_errors[j]) : "not identifiable") << "\n";
  std::cout << "  reduced chi-square " << result.reduced_chi_square << "\n";
  for (const auto &w : result.warnings)
    std::cout << "  warning: " << w << "\n";
  Figures(argc, argv).record("calibration, 4 free parameters to 20 measured values, from existing tables",
                             "under 5 s on one core",
                             seconds(t.first) + ", " + std::to_string(result.iterations) + " iterations");
  std::filesystem::remove_all(dir);
  return 0;
}
