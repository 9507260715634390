// Benchmark of the pilot stage's field level (issue 5): one nozzle-flapper case of RV-1 at its null
// (40 degC, h = x0 = 40 um, dp = p_c - p_r = 10.4 MPa, cavitation on), solved from rest (laminar
// start-up or, from resolution 1.5 on, grid sequencing; similarity continuation) to the default
// convergence criterion (scaled residuals below `Flow solver/Tolerance', flow rate and flapper force
// settled over `Monitor iterations'), with k-epsilon (two-layer) and laminar, at the given mesh
// resolutions (1 is the default; the 20-40 thousand cells are resolutions 2.1-3.0). Prints
// cells, iterations on the case's mesh and on the coarser meshes of the grid sequence, wall time
// (everything: meshing, coarse solves, transfer), C_dn and force. Not a test; the whole sweep is timed by `servodrift flow' (see doc/performance.md).
//   OMP_THREAD_LIMIT=1 build/bench/bench_pilot_field [resolutions, default 1,2] [parameter=value ...]
// (extra arguments are `--set' entries, e.g. 'Flow solver/Report interval=100' for the residual
// history, 'Flow solver/Turbulence model=k-epsilon' for one model only)
#include "bench/benchmarks.h"
#include "bench/figures.h"
#include "common/valve_description.h"
#include "flow/pilot/pilot_field.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace servodrift;
using namespace servodrift::flow;

int servodrift::bench::bench_pilot_field(int argc, char **argv)
{
  std::vector<double> resolutions;
  for (std::string list = argc > 1 ? argv[1] : "1,2"; !list.empty();)
    {
      const std::size_t comma = list.find(',');
      resolutions.push_back(std::atof(list.substr(0, comma).c_str()));
      list = comma == std::string::npos ? "" : list.substr(comma + 1);
    }
  std::vector<std::string> settings{"Output/Progress=none", "Flow solver/Maximum iterations=20000"};
  for (int a = 2; a < argc; ++a)
    settings.emplace_back(argv[a]);
  const ValveDescription valve = load_valve_description("", settings);
  std::printf("RV-1 nozzle-flapper at its null (40 degC, h 40 um, dp 10.4 MPa), from rest, tolerance %.0e\n",
              valve.flow_solver.tolerance);
  std::printf("%-10s %10s %8s %11s %8s %10s %8s %9s\n", "model", "resolution", "cells", "iterations", "coarse",
              "wall [s]", "C_dn", "F [N]");
  std::vector<FlowSolverParameters::Turbulence> models{FlowSolverParameters::Turbulence::k_epsilon,
                                                       FlowSolverParameters::Turbulence::laminar};
  for (int a = 2; a < argc; ++a)
    if (std::string(argv[a]).rfind("Flow solver/Turbulence model=", 0) == 0)
      models = {valve.flow_solver.turbulence};
  auto name = [](FlowSolverParameters::Turbulence t) {
    switch (t)
      {
        case FlowSolverParameters::Turbulence::laminar: return "laminar";
        case FlowSolverParameters::Turbulence::k_epsilon: return "k-epsilon";
        case FlowSolverParameters::Turbulence::k_epsilon_launder_sharma: return "launder-sharma";
        case FlowSolverParameters::Turbulence::k_omega_sst: return "k-omega-sst";
      }
    return "?";
  };
  const Figures figures(argc, argv);
  for (const auto model : models)
    for (const double resolution : resolutions)
      {
        PilotFieldCase c = pilot_field_case(valve, 40);
        c.resolution = resolution;
        c.turbulence = model;
        const auto t0 = std::chrono::steady_clock::now();
        PilotField nozzle(pilot_field_settings(valve), PilotGeometry::nozzle_flapper, c, 40e-6);
        try
          {
            const PilotFieldResult r = nozzle.solve(10.4e6);
            const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            std::printf("%-10s %10.2f %8zu %11u %8u %10.2f %8.4f %9.4f\n", name(model), resolution,
                        nozzle.n_cells(), r.iterations, r.coarse_mesh_iterations, s, r.discharge_coefficient,
                        r.flapper_force);
            figures.record(std::string("RV-1's nozzle at its null from rest, ") + name(model) + ", " +
                             std::to_string(nozzle.n_cells()) + " cells",
                           "no target", seconds(s) + ", " + std::to_string(r.iterations) + " iterations");
          }
        catch (const std::exception &e)
          {
            std::printf("%-10s %10.2f %8zu failed: %s\n", name(model), resolution, nozzle.n_cells(), e.what());
          }
        std::fflush(stdout);
      }
  return 0;
}
