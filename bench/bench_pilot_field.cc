// Benchmark of the pilot stage's field level (issue 5): one nozzle-flapper case of RV-1 at its null
// (40 degC, h = x0 = 40 um, dp = p_c - p_r = 10.4 MPa, cavitation on), solved from rest (laminar
// start-up, similarity continuation) to the default convergence criterion (scaled residuals below
// `Flow solver/Tolerance', flow rate and flapper force settled over `Monitor iterations'), with
// k-epsilon (two-layer) and laminar, at mesh resolutions 1 (the default) and 2 (the 20-40
// thousand cells band is reached near 2.5). Prints cells, iterations, wall time, time per
// iteration, C_dn and force. Not a test; the whole sweep is timed by `servodrift flow' (see
// doc/performance.md).
//   OMP_THREAD_LIMIT=1 build/bench/bench_pilot_field [largest resolution: 1|2|3] [parameter=value ...]
// (extra arguments are `--set' entries, e.g. 'Flow solver/Report interval=100' for the residual history)
#include "common/valve_description.h"
#include "flow/pilot_field.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace servodrift;
using namespace servodrift::flow;

int main(int argc, char **argv)
{
  const double largest = argc > 1 ? std::atof(argv[1]) : 2;
  std::vector<std::string> settings{"Output/Progress=none", "Flow solver/Maximum iterations=20000"};
  for (int a = 2; a < argc; ++a)
    settings.emplace_back(argv[a]);
  const ValveDescription valve = load_valve_description("", settings);
  std::printf("RV-1 nozzle-flapper at its null (40 degC, h 40 um, dp 10.4 MPa), from rest, tolerance %.0e\n",
              valve.flow_solver.tolerance);
  std::printf("%-10s %10s %8s %11s %10s %13s %8s %9s\n", "model", "resolution", "cells", "iterations", "wall [s]",
              "per it. [ms]", "C_dn", "F [N]");
  for (const auto model : {FlowSolverParameters::Turbulence::k_epsilon, FlowSolverParameters::Turbulence::laminar})
    for (double resolution = 1; resolution <= largest; resolution += 1)
      {
        PilotFieldCase c = pilot_field_case(valve, 40);
        c.resolution = resolution;
        c.turbulence = model;
        const auto t0 = std::chrono::steady_clock::now();
        PilotField nozzle(valve, PilotGeometry::nozzle_flapper, c, 40e-6);
        try
          {
            const PilotFieldResult r = nozzle.solve(10.4e6);
            const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            std::printf("%-10s %10.1f %8zu %11u %10.2f %13.2f %8.4f %9.4f\n",
                        model == FlowSolverParameters::Turbulence::laminar ? "laminar" : "k-epsilon", resolution,
                        nozzle.n_cells(), r.iterations, s, 1e3 * s / r.iterations, r.discharge_coefficient, r.flapper_force);
          }
        catch (const std::exception &e)
          {
            std::printf("%-10s %10.1f %8zu failed: %s\n", model == FlowSolverParameters::Turbulence::laminar ? "laminar" : "k-epsilon",
                        resolution, nozzle.n_cells(), e.what());
          }
        std::fflush(stdout);
      }
}
