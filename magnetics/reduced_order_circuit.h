#pragma once
// Reduced-order level of the torque motor: the four-mesh magnetic circuit of model.md 1.2 (E2, E3)
// with thermal gaps (E6, E7), magnet MMF B_r(T) (E8), Maxwell gap forces (E9) and torque (E10).
#include "common/valve_description.h"

#include <array>

namespace servodrift::magnetics
{
  struct CircuitSolution
  {
    std::array<double, 4> gap;      ///< g_1..g_4 [m]
    std::array<double, 4> gap_flux; ///< phi_1..phi_4 [Wb]
    double magnet_flux;             ///< phi_m [Wb]
    double leakage_flux;            ///< phi_l [Wb]
    double armature_flux;           ///< phi_a, control flux through the armature [Wb]
    double torque;                  ///< T_d, positive = closes gaps 1 and 4 [N*m]
  };

  class ReducedOrderCircuit
  {
  public:
    /// All reluctances and the magnet MMF at temperature T [degC].
    ReducedOrderCircuit(const ValveDescription &valve, double temperature);

    /// Solves E3 at armature angle theta [rad] and differential current i [A].
    CircuitSolution solve(double angle, double current) const;
    double torque(double angle, double current) const { return solve(angle, current).torque; }

    double magnet_mmf() const { return mmf; }                 ///< M(T) = B_r l_m/(mu0 mu_rm) (E8) [A]
    double magnet_reluctance() const { return R_m; }          ///< R_m (E2) [A/Wb]
    double leakage_reluctance() const { return R_l; }         ///< R_l [A/Wb]
    double gap_reluctance_at_null() const;                    ///< R_g of the mean gap (E2, E4) [A/Wb]
    double pivot_to_pole_distance() const { return a; }       ///< a(T) [m]
    double mean_gap() const { return 0.5 * (g12 + g34); }     ///< [m]
    double gap_area() const { return w_p * l_p; }             ///< A_g without fringing [m^2]

  private:
    double a, w_p, l_p, g12, g34;
    bool fringing;
    double mmf, R_m, R_l, R_c, R_a, effective_turns;

    double gap_area(double g) const;
  };
} // namespace servodrift::magnetics
