#pragma once
// The structure stage: computes the spring_tube table over the table temperatures at the model
// level chosen by `Spring tube/Model level'.
#include "common/table.h"
#include "common/valve_description.h"

namespace servodrift::structure
{
  Table compute_spring_tube_table(const ValveDescription &valve);
  /// Computes the table and writes tables/spring_tube.csv (rank 0).
  void run(const ValveDescription &valve);
} // namespace servodrift::structure
