// Mesh convergence of the pilot stage's nozzle-flapper cases (issue 28, item 5): RV-1 at 40 degC,
// dp = 10.4 MPa (the null's nozzle pressure), the default flow model (two-layer k-epsilon), at the
// null gap and the ends of the default table's gap range, single phase and cavitating, each solved
// from rest at mesh resolutions 1, 2 and 3 (cell counts 1 : 4 : 9). Richardson extrapolation from the
// three (h = 1/resolution, the observed order p from the three values, bounded to [0.5, 4]) gives
// the mesh-converged value and the default mesh's error. Not a test.
//   OMP_THREAD_LIMIT=1 build/bench/bench_mesh_convergence [gaps in um, default 10,40,70] [cavitation: 0|1|both]
#include "bench/benchmarks.h"
#include "common/valve_description.h"
#include "flow/pilot_field.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace servodrift;
using namespace servodrift::flow;

namespace
{
  /// Richardson extrapolation of f(h) = f0 + C h^p from values at h1 > h2 > h3: f0 and p.
  std::pair<double, double> richardson(const double f[3], const double h[3])
  {
    // solve (f1 - f2)/(f2 - f3) = (h1^p - h2^p)/(h2^p - h3^p) for p by bisection on [0.5, 4]
    auto ratio = [&](double p) {
      return (std::pow(h[0], p) - std::pow(h[1], p)) / (std::pow(h[1], p) - std::pow(h[2], p));
    };
    const double target = (f[0] - f[1]) / (f[1] - f[2]);
    double lo = 0.5, hi = 4, p = 2;
    if (!(target > 0) || !std::isfinite(target))
      p = 2; // non-monotone: report with the nominal second order
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
  std::printf("RV-1 nozzle-flapper, 40 degC, dp %.1f MPa, k-epsilon (two-layer), from rest\n", dp * 1e-6);
  std::printf("%6s %9s %10s %7s %11s %9s %9s %8s\n", "gap", "cavitates", "resolution", "cells", "iterations", "wall [s]",
              "C_dn", "F [N]");
  for (const double gap : gaps)
    for (const bool cavitation : cavitation_modes)
      {
        ValveDescription v = base;
        v.pilot.field_solution.cavitation = cavitation;
        double C[3] = {0, 0, 0}, F[3] = {0, 0, 0};
        bool all = true;
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
                C[j] = r.discharge_coefficient, F[j] = r.flapper_force;
                std::printf("%6.0f %9s %10.0f %7zu %11u %9.1f %9.5f %8.5f\n", gap * 1e6, cavitation ? "yes" : "no",
                            resolutions[j], nozzle.n_cells(), r.iterations + r.coarse_mesh_iterations,
                            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
                            r.discharge_coefficient, r.flapper_force);
              }
            catch (const std::exception &e)
              {
                all = false;
                std::printf("%6.0f %9s %10.0f %7zu failed: %s\n", gap * 1e6, cavitation ? "yes" : "no", resolutions[j],
                            nozzle.n_cells(), e.what());
              }
            std::fflush(stdout);
          }
        if (!all)
          continue;
        const double h[3] = {1, 0.5, 1.0 / 3};
        const auto [C0, pC] = richardson(C, h);
        const auto [F0, pF] = richardson(F, h);
        std::printf("  extrapolated: C_dn %.5f (order %.2f; resolution 1 %+.2f %%, 2 %+.2f %%), F %.5f N (order %.2f; "
                    "resolution 1 %+.2f %%, 2 %+.2f %%)\n",
                    C0, pC, 100 * (C[0] / C0 - 1), 100 * (C[1] / C0 - 1), F0, pF, 100 * (F[0] / F0 - 1),
                    100 * (F[1] / F0 - 1));
        std::fflush(stdout);
      }
  return 0;
}
