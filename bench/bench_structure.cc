// Benchmark of the field-level spring tube (issue 6): one temperature at resolutions 1, 2 and 4
// (mesh, assembly, one factorisation, two solves; then the stress evaluation and the VTU), best of
// the repetitions. Not a test.
//   OMP_THREAD_LIMIT=1 build/bench/bench_structure [repetitions]
// The default sweep (9 temperatures, with the VTU files) is timed with the command itself:
//   time build/servodrift structure -o /tmp/bench
#include "bench/benchmarks.h"
#include "bench/figures.h"
#include "common/valve_description.h"
#include "structure/spring_tube_field.h"
#include "structure/spring_tube_stage.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace servodrift;

int servodrift::bench::bench_structure(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const int repetitions = argc > 1 ? std::atoi(argv[1]) : 3;
  using clock = std::chrono::steady_clock;
  auto seconds = [](clock::time_point a, clock::time_point b) { return std::chrono::duration<double>(b - a).count(); };

  const Figures figures(argc, argv);
  std::printf("| resolution | cells | unknowns | K_a [N*m/rad] | solve [s] | stress [s] | VTU [s] |\n|---|---|---|---|---|---|---|\n");
  for (const char *resolution : {"1", "2", "4"})
    {
      const ValveDescription valve = load_valve_description(
        "", {"Output/Progress=none", std::string("Spring tube/Field mesh resolution=") + resolution});
      double solve = 1e9, stress = 1e9, vtu = 1e9, K = 0;
      unsigned int cells = 0, dofs = 0;
      for (int k = 0; k < repetitions; ++k)
        {
          const auto t0 = clock::now();
          const auto field = structure::spring_tube_field(valve, 40);
          const auto t1 = clock::now();
          const structure::TopLoad rated{field->rotational_stiffness() * structure::rated_armature_angle(valve), 0};
          const auto peak = field->peak_stress(rated, 1e-4);
          const auto t2 = clock::now();
          field->write_vtu("/tmp/bench_structure.vtu", rated);
          const auto t3 = clock::now();
          solve = std::min(solve, seconds(t0, t1));
          stress = std::min(stress, seconds(t1, t2));
          vtu = std::min(vtu, seconds(t2, t3));
          K = field->rotational_stiffness();
          (void)peak;
          cells = field->n_cells();
          dofs = field->n_dofs();
        }
      std::printf("| %s | %u | %u | %.5f | %.3f | %.3f | %.3f |\n", resolution, cells, dofs, K, solve, stress, vtu);
      figures.record("spring tube, one temperature at resolution " + std::string(resolution) + " (" +
                       std::to_string(dofs) + " unknowns): mesh, assembly, factorisation, two solves",
                     std::string(resolution) == "1" ? "under 10 s" : "no target", servodrift::bench::seconds(solve));
    }
  std::remove("/tmp/bench_structure.vtu");
  return 0;
}
