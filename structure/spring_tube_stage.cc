#include "structure/spring_tube_stage.h"

#include "common/stage_output.h"
#include "common/sweep.h"
#include "structure/spring_tube_beam.h"

namespace servodrift::structure
{
  Table compute_spring_tube_table(const ValveDescription &valve)
  {
    const auto &T = valve.sweeps.table_temperatures;
    Table table(schemas::spring_tube);
    table.rows = run_sweep(
      "structure", T.size(),
      [&](std::size_t k) {
        return CaseRows{{T[k], beam_tube(valve, T[k]).rotational_stiffness, flags::computed}};
      },
      valve.output.progress);
    return table;
  }

  void run(const ValveDescription &valve)
  {
    Table table = compute_spring_tube_table(valve);
    write_table(valve, table, "structure/" + valve.spring_tube.model_level);
  }
} // namespace servodrift::structure
