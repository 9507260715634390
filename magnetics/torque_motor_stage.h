#pragma once
// The magnetics stage: the torque_motor table over Sweeps (temperature x angle x current) at the
// model level chosen by `Torque motor/Model level', and the studies of the field level.
#include "common/table.h"
#include "common/valve_description.h"

namespace servodrift::magnetics
{
  /// Every MPI rank returns the whole table (the cases are shared over the ranks). At the field
  /// level, the mirror image (-theta, -i) of a solved case is not solved again (T(-theta, -i) =
  /// -T(theta, i) on the mirrored mesh), and VTU files of the cases chosen by `Output/Magnetics fields' and magnetics/field_summary.csv
  /// are written too.
  Table compute_torque_motor_table(const ValveDescription &valve);

  /// Computes the table and writes tables/torque_motor.csv (rank 0).
  void run(const ValveDescription &valve);

  /// C10: the in-plane magnet width at which the field model's mean working-gap flux density at
  /// theta = 0, i = 0, T0 equals the circuit's; writes magnetics/calibration.csv, prints the setting.
  void calibrate(const ValveDescription &valve);

  /// Mesh convergence of T(0.1 deg), K_m and K_t on the default mesh refined 0, 1, 2 times, with the observed
  /// order, and the torque's sensitivity to the outer boundary radius; writes
  /// magnetics/convergence.csv and magnetics/boundary_study.csv.
  void convergence_study(const ValveDescription &valve);
} // namespace servodrift::magnetics
