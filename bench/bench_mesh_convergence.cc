// Mesh convergence of the pilot stage's nozzle-flapper cases (issue 28, item 5): RV-1 at 40 degC,
// dp = 10.4 MPa (the null's nozzle pressure), the default flow model (two-layer k-epsilon), at the
// null gap and the ends of the default table's gap range, single phase and cavitating, each solved
// from rest at mesh resolutions 1, 2 and 3 (cell counts 1 : 4 : 9). Richardson extrapolation from the
// three (h = 1/resolution, the observed order p from the three values, bounded to [0.5, 4]) gives
// the mesh-converged value and the default mesh's error; where the finest mesh fails, the two
// coarser ones with the nominal second order. Not a test.
//   OMP_THREAD_LIMIT=1 build/bench/bench_mesh_convergence [gaps in um, default 10,40,70] [cavitation: 0|1|both]
// Writes nozzle_mesh_errors.csv to $SERVODRIFT_BENCH_RESULTS (doc/benchmarks/, where the program
// reads the errors it states in tables/nozzle_flapper.csv's header) or to the working directory.
#include "bench/benchmarks.h"
#include "common/csv.h"
#include "common/output_files.h"
#include "common/valve_description.h"
#include "flow/pilot/pilot_field.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

using namespace servodrift;
using namespace servodrift::flow;

namespace
{
  /// Richardson extrapolation of f(h) = f0 + C h^p from values at h1 > h2 > h3: f0 and p (2 where
  /// the three are not monotone, `monotone' then false).
  std::pair<double, double> richardson(const double f[3], const double h[3], bool &monotone)
  {
    // solve (f1 - f2)/(f2 - f3) = (h1^p - h2^p)/(h2^p - h3^p) for p by bisection on [0.5, 4]
    auto ratio = [&](double p) {
      return (std::pow(h[0], p) - std::pow(h[1], p)) / (std::pow(h[1], p) - std::pow(h[2], p));
    };
    const double target = (f[0] - f[1]) / (f[1] - f[2]);
    double lo = 0.5, hi = 4, p = 2;
    monotone = target > 0 && std::isfinite(target);
    if (!monotone)
      p = 2; // report with the nominal second order
    else
      {
        for (int i = 0; i < 60; ++i)
          {
            p = 0.5 * (lo + hi);
            (ratio(p) < target ? lo : hi) = p; // ratio grows with p for h1 > h2 > h3
          }
      }
    const double C = (f[1] - f[2]) / (std::pow(h[1], p) - std::pow(h[2], p));
    return {f[2] - C * std::pow(h[2], p), p};
  }
} // namespace

int servodrift::bench::bench_mesh_convergence(int argc, char **argv)
{
  std::vector<double> gaps{10e-6, 40e-6, 70e-6};
  if (argc > 1)
    {
      gaps.clear();
      for (std::string list = argv[1]; !list.empty();)
        {
          const std::size_t comma = list.find(',');
          gaps.push_back(1e-6 * std::atof(list.substr(0, comma).c_str()));
          list = comma == std::string::npos ? "" : list.substr(comma + 1);
        }
    }
  const std::string which = argc > 2 ? argv[2] : "both";
  std::vector<bool> cavitation_modes;
  if (which != "0")
    cavitation_modes.push_back(true);
  if (which != "1")
    cavitation_modes.push_back(false);
  const ValveDescription base =
    load_valve_description("", {"Output/Progress=none", "Flow solver/Maximum iterations=30000"});
  const double dp = 10.4e6, resolutions[3] = {1, 2, 3};
  CsvDocument errors;
  errors.comments = {"servodrift-bench nozzle_mesh_errors",
                     "RV-1's nozzle-flapper case at 40 degC and 10.4 MPa, two-layer k-epsilon, each from rest at mesh "
                     "resolutions 1, 2 and 3; error = value / Richardson-extrapolated value - 1 (three levels, the "
                     "observed order within 0.5-4, 2 where they are not monotone; two levels with order 2 where "
                     "the finest fails)",
                     "command OMP_THREAD_LIMIT=1 build/bench/bench_mesh_convergence" +
                       (argc > 1 ? " " + std::string(argv[1]) : std::string()) +
                       (argc > 2 ? " " + std::string(argv[2]) : std::string())};
  errors.columns = {"gap[m]", "cavitation", "resolution[1]", "cells", "discharge_coefficient[1]", "flapper_force[N]",
                    "estimate", "discharge_coefficient_error[1]", "flapper_force_error[1]"};
  std::printf("RV-1 nozzle-flapper, 40 degC, dp %.1f MPa, k-epsilon (two-layer), from rest\n", dp * 1e-6);
  std::printf("%6s %9s %10s %7s %11s %9s %9s %8s\n", "gap", "cavitates", "resolution", "cells", "iterations", "wall [s]",
              "C_dn", "F [N]");
  for (const double gap : gaps)
    for (const bool cavitation : cavitation_modes)
      {
        ValveDescription v = base;
        v.pilot.field_solution.cavitation = cavitation;
        double C[3] = {0, 0, 0}, F[3] = {0, 0, 0};
        std::size_t cells[3] = {0, 0, 0};
        int solved = 0; // the resolutions solved, coarsest first
        for (int j = 0; j < 3; ++j)
          {
            PilotFieldCase c = pilot_field_case(v, 40);
            c.resolution = resolutions[j];
            c.turbulence = FlowSolverParameters::Turbulence::k_epsilon;
            const auto t0 = std::chrono::steady_clock::now();
            PilotField nozzle(pilot_field_settings(v), PilotGeometry::nozzle_flapper, c, gap);
            try
              {
                const PilotFieldResult r = nozzle.solve(dp);
                C[j] = r.discharge_coefficient, F[j] = r.flapper_force, cells[j] = nozzle.n_cells();
                solved += solved == j;
                std::printf("%6.0f %9s %10.0f %7zu %11u %9.1f %9.5f %8.5f\n", gap * 1e6, cavitation ? "yes" : "no",
                            resolutions[j], nozzle.n_cells(), r.iterations + r.coarse_mesh_iterations,
                            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
                            r.discharge_coefficient, r.flapper_force);
              }
            catch (const std::exception &e)
              {
                std::printf("%6.0f %9s %10.0f %7zu failed: %s\n", gap * 1e6, cavitation ? "yes" : "no", resolutions[j],
                            nozzle.n_cells(), e.what());
              }
            std::fflush(stdout);
          }
        if (solved < 2)
          continue;
        const double h[3] = {1, 0.5, 1.0 / 3};
        // two levels: f0 = f2 + (f2 - f1)/(2^2 - 1), the nominal second order at h halved
        bool C_monotone = true, F_monotone = true;
        const auto [C0, pC] = solved == 3 ? richardson(C, h, C_monotone) : std::pair{C[1] + (C[1] - C[0]) / 3, 2.0};
        const auto [F0, pF] = solved == 3 ? richardson(F, h, F_monotone) : std::pair{F[1] + (F[1] - F[0]) / 3, 2.0};
        const auto order = [](double p, bool monotone) {
          char s[48];
          std::snprintf(s, sizeof s, monotone ? "order %.1f" : "not monotone: order 2", p);
          return std::string(s);
        };
        const std::string estimate = solved == 3 ? "three levels (C_dn " + order(pC, C_monotone) + "; force " +
                                                     order(pF, F_monotone) + ")" :
                                                   "two levels: order 2";
        std::printf("  extrapolated (%s): C_dn %.5f (order %.2f; resolution 1 %+.2f %%, 2 %+.2f %%), F %.5f N (order "
                    "%.2f; resolution 1 %+.2f %%, 2 %+.2f %%)\n",
                    estimate.c_str(), C0, pC, 100 * (C[0] / C0 - 1), 100 * (C[1] / C0 - 1), F0, pF,
                    100 * (F[0] / F0 - 1), 100 * (F[1] / F0 - 1));
        std::fflush(stdout);
        for (int j = 0; j < solved; ++j)
          errors.rows.push_back({format_cell(gap), cavitation ? "on" : "off", format_cell(resolutions[j]),
                                 std::to_string(cells[j]), format_cell(C[j]), format_cell(F[j]), estimate,
                                 format_cell(C[j] / C0 - 1), format_cell(F[j] / F0 - 1)});
      }
  const char *results = std::getenv("SERVODRIFT_BENCH_RESULTS");
  const std::string file = std::string(results ? results : ".") + "/nozzle_mesh_errors.csv";
  std::ofstream(file) << errors.text();
  std::printf("errors written to %s\n", file.c_str());
  return 0;
}
