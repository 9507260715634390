#pragma once
// Lumped coefficients read off the coefficient tables, whatever level produced them: the torque
// motor's K_m and K_t (model.md E4, C1). Used by the fits (E25) and by the report.
#include "common/grid_function.h"

namespace servodrift
{
  struct TorqueMotorCoefficients
  {
    double temperature;              ///< [degC]
    double torque_at_tenth_degree;   ///< T(theta = 0.1 deg, i = 0) [N*m]
    double secant_magnetic_spring;   ///< K_m = T(0.1 deg, 0)/(0.1 deg), the paper's measure (C1) [N*m/rad]
    double magnetic_spring;          ///< K_m = dT/dtheta at theta = 0, i = 0 [N*m/rad]
    double torque_constant;          ///< K_t = dT/di at theta = 0, i = 0 [N*m/A]
  };

  /// From a torque(T, theta, i) grid function. The derivatives are central differences over the
  /// first grid step h and over 2h, combined by Richardson extrapolation (error O(h^4)).
  TorqueMotorCoefficients torque_motor_coefficients(const GridFunction &torque, double temperature);
} // namespace servodrift
