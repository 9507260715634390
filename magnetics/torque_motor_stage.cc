#include "magnetics/torque_motor_stage.h"

#include "common/stage_output.h"
#include "common/sweep.h"
#include "magnetics/reduced_order_circuit.h"

namespace servodrift::magnetics
{
  Table compute_torque_motor_table(const ValveDescription &valve)
  {
    const auto &sw = valve.sweeps;
    const std::size_t n_angles = sw.motor_angles.size();
    // One case per (temperature, angle); each case gives one row per current.
    const auto compute_case = [&](std::size_t k) {
      const double T = sw.table_temperatures[k / n_angles];
      const double theta = sw.motor_angles[k % n_angles];
      const ReducedOrderCircuit circuit(valve, T);
      CaseRows rows;
      for (double i : sw.motor_currents)
        // the circuit is solved exactly: no discretisation error to report
        rows.push_back({T, theta, i, circuit.torque(theta, i), 0.0, flags::computed});
      return rows;
    };
    Table table(schemas::torque_motor);
    table.rows = run_sweep("magnetics", sw.table_temperatures.size() * n_angles, compute_case, valve.output.progress);
    return table;
  }

  void run(const ValveDescription &valve)
  {
    Table table = compute_torque_motor_table(valve);
    write_table(valve, table, "magnetics/" + valve.torque_motor.model_level);
  }
} // namespace servodrift::magnetics
