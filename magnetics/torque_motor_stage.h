#pragma once
// The magnetics stage: computes the torque_motor table over Sweeps (temperature x angle x current)
// at the model level chosen by `Torque motor/Model level'.
#include "common/table.h"
#include "common/valve_description.h"

namespace servodrift::magnetics
{
  /// Every MPI rank returns the whole table (the cases are shared over the ranks).
  Table compute_torque_motor_table(const ValveDescription &valve);

  /// Computes the table and writes tables/torque_motor.csv (rank 0).
  void run(const ValveDescription &valve);
} // namespace servodrift::magnetics
