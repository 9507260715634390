#include "magnetics/torque_motor_stage.h"

#include "common/stage_output.h"
#include "common/sweep.h"
#include "common/units.h"

#include <algorithm>
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
      // Paper preset (D2): the linear magnetic spring follows E25 instead of the circuit's secant
      // K_m (C1), the nonlinear and current-driven parts stay the circuit's.
      double spring_correction = 0, flag = flags::computed;
      if (valve.torque_motor.paper_magnetic_spring)
        {
          const double tenth = 0.1 * units::degree;
          // E25 was fitted over 40..120 degC only: clamped to that window outside it, and flagged (C6)
          const double T_fit = std::clamp(T, 40.0, 120.0);
          spring_correction = (11.61 - 0.004837 * T_fit) - circuit.torque(tenth, 0) / tenth; // E25
          if (T_fit != T)
            flag = flags::clamped;
        }
      CaseRows rows;
      for (double i : sw.motor_currents)
        // the circuit is solved exactly: no discretisation error to report
        rows.push_back({T, theta, i, circuit.torque(theta, i) + spring_correction * theta, 0.0, flag});
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
