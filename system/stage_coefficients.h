#pragma once
// The lumped coefficients of the three stages at a temperature, read off the tables through the
// valve model (K_m, K_t, K_a, C_d0 and C_dn at null, flow-force stiffness, flapper force
// difference): what the report compares with model.md and the paper.
#include "common/table_coefficients.h"
#include "system/valve_model.h"

#include <vector>

namespace servodrift::system
{
  struct StageCoefficients
  {
    double temperature;              ///< [degC]
    TorqueMotorCoefficients motor;   ///< K_m (secant and slope), K_t, T(0.1 deg)
    double spring_stiffness;         ///< K_a [N*m/rad]
    double flow_force_stiffness;     ///< K_f at null, blocked spool (E24) [N/m]
    double null_control_pressure;    ///< p_L = p_R at x_f = 0 [Pa]
    double orifice_discharge;        ///< C_d0 at null [1]
    double nozzle_discharge;         ///< C_dn at null [1]
    double null_flapper_force;       ///< the flapper force of one nozzle at null [N]
    double quiescent_flow;           ///< both nozzles at null [m^3/s]
    double force_difference_10um;    ///< F_L - F_R at x_f = 10 um (self-consistent bridge) [N]
    double net_stiffness;            ///< K_a - K_m + r^2 K_f, static stability (1.12) [N*m/rad]
  };

  StageCoefficients stage_coefficients(const ValveModel &model, double temperature);
} // namespace servodrift::system
