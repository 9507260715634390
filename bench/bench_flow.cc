// Benchmark of the finite-volume solver core (issue 4): laminar axisymmetric pipe flow (Hagen-
// Poiseuille with a parabolic inlet, R = 1, L = 4 R, Re = rho U 2R / mu = 200) converged to scaled
// residuals of 1e-8 on about 5, 20 and 80 thousand cells, with the other momentum solvers, the coupled
// pressure-velocity iterations and two velocity relaxations on the 20-thousand-cell mesh. Prints
// cells, outer iterations, wall time, time per iteration and the pressure-drop error. Not a test.
//   OMP_THREAD_LIMIT=1 build/bench/bench_flow [repetitions] [largest cells in thousands: 5|20|80] [compare: 1|0|2]
#include "bench/benchmarks.h"
#include "bench/figures.h"
#include "common/gmsh_mesh.h"
#include "common/output_files.h"
#include "common/valve_description.h"
#include "flow/fv/simplec.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>

using namespace servodrift;
using namespace servodrift::flow;

namespace
{
  struct Timing
  {
    std::size_t cells;
    unsigned int iterations;
    double seconds, pressure_drop_error;
  };

  Timing pipe(const FvMesh &mesh, FlowSolverParameters settings)
  {
    const double U = 1, R = 1, L = 4, mu = 0.01, rho = 1;
    std::map<std::string, BoundaryCondition> bc{
      {"left", BoundaryCondition::velocity_inlet([&](const Vector2 &x) { return Vector2(2 * U * (1 - x.y() * x.y() / (R * R)), 0); })},
      {"right", BoundaryCondition::pressure_outlet(0)},
      {"top", BoundaryCondition::wall()},
      {"bottom", BoundaryCondition::axis()}};
    const auto t0 = std::chrono::steady_clock::now();
    SimplecSolver solver(mesh, {rho, mu}, bc, settings);
    const SolveReport report = solver.solve();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double dp = solver.mean_pressure("left") - solver.mean_pressure("right");
    return {mesh.n_cells(), report.iterations, seconds, dp / (8 * mu * U * L / (R * R)) - 1};
  }
} // namespace

int servodrift::bench::bench_flow(int argc, char **argv)
{
  const int repetitions = argc > 1 ? std::atoi(argv[1]) : 3;
  const int largest = argc > 2 ? std::atoi(argv[2]) : 80;
  // 1: the momentum solvers, the coupled solver and alpha_u on the 20 k mesh; 2: the coupled solver only
  const int compare = argc > 3 ? std::atoi(argv[3]) : 1;
  // tolerance 1e-8 as recorded in doc/performance.md (the default is 1e-6 since issue 5)
  const ValveDescription valve = load_valve_description("", {"Output/Progress=none", "Flow solver/Tolerance=1e-8"});
  const GmshTemplate geo{"rectangle.geo", read_file(std::string(SERVODRIFT_SOURCE_DIR) + "/tests/verification/meshes/rectangle.geo"), 1.0, ""};
  auto mesh_of = [&](int nx, int ny) {
    return FvMesh(mesh_template_all_groups(geo, {{"x0", 0}, {"x1", 4}, {"y0", 0}, {"y1", 1}, {"nx", double(nx)}, {"ny", double(ny)}}),
                  Geometry::axisymmetric, "rectangle.geo");
  };
  auto best_of = [&](const FvMesh &mesh, const FlowSolverParameters &s) {
    std::vector<Timing> runs;
    for (int k = 0; k < repetitions; ++k)
      runs.push_back(pipe(mesh, s));
    std::sort(runs.begin(), runs.end(), [](const Timing &a, const Timing &b) { return a.seconds < b.seconds; });
    return std::make_pair(runs.front(), runs[runs.size() / 2].seconds);
  };
  auto print = [&](const char *what, const std::pair<Timing, double> &r) {
    std::printf("  %-34s %6zu cells %5u iterations %7.3f s (median %7.3f s) %6.2f ms/iteration  dp error %+.2e\n",
                what, r.first.cells, r.first.iterations, r.first.seconds, r.second,
                1e3 * r.first.seconds / r.first.iterations, r.first.pressure_drop_error);
  };

  std::printf("axisymmetric pipe, Re = 200, tolerance 1e-8, best of %d (default settings: %s convection, alpha_u %.2f)\n",
              repetitions,
              valve.flow_solver.convection == FlowSolverParameters::Convection::upwind ? "upwind" : "bounded linear upwind",
              valve.flow_solver.velocity_relaxation);
  const Figures figures(argc, argv);
  const int sizes[3][2] = {{160, 32}, {320, 64}, {640, 128}};
  for (const auto &size : sizes)
    {
      if (size[0] * size[1] > largest * 1100)
        break;
      const FvMesh mesh = mesh_of(size[0], size[1]);
      const auto r = best_of(mesh, valve.flow_solver);
      print("default (BiCGSTAB-Jacobi)", r);
      figures.record("axisymmetric pipe flow, " + std::to_string(r.first.cells) + " cells, to scaled residuals of 1e-8",
                     r.first.cells == 20480 ? "under 5 s on one core" : "no target",
                     seconds(r.first.seconds) + ", " + std::to_string(r.first.iterations) + " iterations");
    }
  if (!compare)
    return 0;
  const FvMesh mesh = mesh_of(320, 64);
  FlowSolverParameters coupled = valve.flow_solver;
  coupled.coupling = FlowSolverParameters::Coupling::coupled;
  auto print_coupled = [&] { print("coupled pressure-velocity (UMFPACK)", best_of(mesh, coupled)); };
  if (compare == 2)
    {
      print_coupled();
      return 0;
    }
  for (auto [solver, name] : {std::make_pair(FlowSolverParameters::MomentumSolver::bicgstab_gauss_seidel, "BiCGSTAB-Gauss-Seidel"),
                              std::make_pair(FlowSolverParameters::MomentumSolver::bicgstab_ilu, "BiCGSTAB-ILUT momentum"),
                              std::make_pair(FlowSolverParameters::MomentumSolver::direct, "UMFPACK momentum")})
    {
      FlowSolverParameters s = valve.flow_solver;
      s.momentum_solver = solver;
      print(name, best_of(mesh, s));
    }
  print_coupled();
  for (double alpha : {0.8, 0.95})
    {
      FlowSolverParameters s = valve.flow_solver;
      s.velocity_relaxation = alpha;
      char name[64];
      std::snprintf(name, sizeof name, "alpha_u %.2f", alpha);
      print(name, best_of(mesh, s));
    }
  return 0;
}
