// Benchmark of the field-level torque motor (issue 3): one (T, theta, i) case at the default
// resolution from scratch (meshing, set-up, cold Newton) and warm (as inside a sweep), each on the
// table's mesh and on its error mesh (half the resolution: the table's torque_error), as the stage
// solves them, with unknowns, Newton iterations and time per case. Not a test.
//   OMP_THREAD_LIMIT=1 build/bench/bench_magnetics [repetitions]
// The default sweep (12 temperatures x 9 angles x 7 currents) is timed with the command itself, by
// scripts/run-benchmarks: mpirun -np 2 build/servodrift magnetics -o /tmp/bench
#include "bench/benchmarks.h"
#include "bench/figures.h"
#include "common/units.h"
#include "common/valve_description.h"
#include "magnetics/torque_motor_field.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>

using namespace servodrift;

int servodrift::bench::bench_magnetics(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const int repetitions = argc > 1 ? std::atoi(argv[1]) : 3;
  const ValveDescription valve = load_valve_description("", {"Output/Progress=none"});
  using clock = std::chrono::steady_clock;
  auto seconds = [](clock::time_point a, clock::time_point b) { return std::chrono::duration<double>(b - a).count(); };

  std::vector<double> setup, cold, warm;
  unsigned int dofs = 0, error_dofs = 0, cold_iterations = 0, warm_iterations = 0;
  const double loose = magnetics::error_mesh_tolerance(valve);
  for (int k = 0; k < repetitions; ++k)
    {
      const auto t0 = clock::now();
      magnetics::TorqueMotorFieldModel model(valve, 40); // gmsh meshing, DoFs, symbolic factorisations
      magnetics::TorqueMotorFieldModel error_mesh(valve, 40,
                                                  magnetics::error_mesh_resolution_ratio *
                                                    valve.torque_motor.field_mesh_resolution);
      const auto t1 = clock::now();
      const auto a = model.torque(0.1 * units::degree, 0.0); // from A = 0
      error_mesh.torque(0.1 * units::degree, 0.0, false, loose);
      const auto t2 = clock::now();
      // the next angle at this current, as the sweep takes it (its start: the parabola through the
      // last solves needs three; here the last solution)
      const auto b = model.torque(0.15 * units::degree, 0.0);
      error_mesh.torque(0.15 * units::degree, 0.0, false, loose);
      const auto t3 = clock::now();
      setup.push_back(seconds(t0, t1));
      cold.push_back(seconds(t1, t2));
      warm.push_back(seconds(t2, t3));
      dofs = model.n_dofs();
      error_dofs = error_mesh.n_dofs();
      cold_iterations = a.newton.iterations;
      warm_iterations = b.newton.iterations;
    }
  auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  std::printf("torque motor field model at 40 degC, default resolution: %u unknowns (FE_Q(%u)), error mesh %u\n", dofs,
              valve.torque_motor.field_element_degree, error_dofs);
  std::printf("  meshing and set-up, both meshes:             %.3f s (median of %d)\n", median(setup), repetitions);
  std::printf("  first case (0.1 deg, 0 A) from A = 0:        %.3f s, %u Newton iterations at the case\n", median(cold),
              cold_iterations);
  std::printf("  next case (0.15 deg, 0 A), warm start:       %.3f s, %u Newton/chord iterations at the case\n",
              median(warm), warm_iterations);
  std::printf("  (each case: the solve and the stress tensor, on the table's mesh and on the error mesh)\n");
  const Figures figures(argc, argv);
  figures.record("torque motor, one (T, theta, i) case from A = 0 (" + std::to_string(dofs) + " unknowns, error mesh " +
                   std::to_string(error_dofs) + ")",
                 "under 1 s", servodrift::bench::seconds(median(cold)));
  figures.record("the next case, warm (as inside a sweep)", "no target", servodrift::bench::seconds(median(warm)));
  figures.record("meshing and set-up of both meshes, once per temperature", "no target",
                 servodrift::bench::seconds(median(setup)));
  return 0;
}
