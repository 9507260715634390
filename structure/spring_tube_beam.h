#pragma once
// Reduced-order level of the spring tube: Euler-Bernoulli tube loaded by an end moment (model.md
// 1.6, E11-E13), with the full 2x2 tip compliance for moment and shear as a reference for the FEM.
#include "common/valve_description.h"

namespace servodrift::structure
{
  struct BeamTube
  {
    double youngs_modulus;        ///< E(T) (E12) [Pa]
    double second_moment;         ///< I = pi (D^4 - d^4)/64 [m^4]
    double length;                ///< l(T) [m]
    double outer_radius;          ///< D(T)/2, the outer fibre [m]
    double rotational_stiffness;  ///< K_a = E I/l (E11) [N*m/rad]

    /// Tip rotation and deflection under an end moment M and shear V (1.6):
    /// theta = (M l + V l^2/2)/(E I),  delta = (M l^2/2 + V l^3/3)/(E I).
    double tip_rotation(double moment, double shear) const;
    double tip_deflection(double moment, double shear) const;
  };

  /// The tube at temperature T [degC]: E(T) and D, d, l grown with alpha_s (E12, E13).
  BeamTube beam_tube(const ValveDescription &valve, double temperature);
} // namespace servodrift::structure
