#include "system/stage_coefficients.h"

namespace servodrift::system
{
  StageCoefficients stage_coefficients(const ValveModel &model, double T)
  {
    const auto &valve = model.description();
    const auto &f = model.functions();
    const double p_s = valve.operating.supply_pressure, p_r = valve.operating.return_pressure;
    const double r = valve.armature.pivot_to_nozzle_distance;
    StageCoefficients c;
    c.temperature = T;
    c.motor = torque_motor_coefficients(f.torque, T);
    c.spring_stiffness = f.stiffness(T);
    c.flow_force_stiffness = model.flow_force_stiffness(T);
    const BridgeState null = model.bridge(T, 0.0);
    c.null_control_pressure = null.left_pressure;
    c.orifice_discharge = f.orifice_discharge(T, p_s - null.left_pressure);
    c.nozzle_discharge = f.nozzle_discharge(T, null.left_gap, null.left_pressure - p_r);
    c.null_flapper_force = null.left_force;
    c.quiescent_flow = null.left_flow + null.right_flow;
    const BridgeState deflected = model.bridge(T, 10e-6);
    c.force_difference_10um = deflected.left_force - deflected.right_force;
    c.net_stiffness = c.spring_stiffness - c.motor.magnetic_spring + r * r * c.flow_force_stiffness;
    return c;
  }
} // namespace servodrift::system
