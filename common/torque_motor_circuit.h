#pragma once
// The torque motor's four-mesh magnetic circuit of model.md 1.2 (E2, E3) with thermal gaps (E6, E7),
// magnet MMF B_r(T) (E8), Maxwell gap forces (E9) and torque (E10): the reduced-order level of the
// magnetics stage, and what maps a build mismatch of the motor (a gap ground unevenly, magnets of
// different remanence) to its magnetic null and stiffness in the system model's tolerance study.
// In common/ because both use it.
#include "common/valve_description.h"

#include <array>

namespace servodrift
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

  /// A torque motor built off nominal (model.md 1.2, issue 25; doc/method.md "Asymmetric valve").
  struct MagneticMismatch
  {
    /// g_1 - g_2 at theta = 0: the lower pole piece's two faces ground to different heights; the
    /// lower gaps are g_12 +- mismatch/2 [m]
    double lower_gap_mismatch = 0;
    /// relative remanence deviation of each magnet, (B_r,k - B_r)/B_r [1]. E3 has the magnets in
    /// parallel between the pole pieces, so the circuit feels their mean only.
    double left_remanence = 0, right_remanence = 0;
    bool any() const { return lower_gap_mismatch != 0 || left_remanence != 0 || right_remanence != 0; }
  };

  class TorqueMotorCircuit
  {
  public:
    /// All reluctances and the magnet MMF at temperature T [degC], of a motor built with `mismatch'.
    TorqueMotorCircuit(const ValveDescription &valve, double temperature, const MagneticMismatch &mismatch = {});

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
    double a, w_p, l_p, g12, g34, lower_mismatch;
    bool fringing;
    double mmf, R_m, R_l, R_c, R_a, effective_turns;

    double gap_area(double g) const;
  };

  /// What a motor mismatch does at T, read off E3 by comparing the mismatched and the nominal
  /// circuit: the angle where the mismatched motor gives no torque at zero current, and the ratios
  /// of its K_m (slope in angle there) and K_t (slope in current there) to the nominal ones at 0.
  struct MismatchEffect
  {
    double null_angle = 0;            ///< [rad]
    double magnetic_spring_ratio = 1; ///< K_m'/K_m [1]
    double torque_constant_ratio = 1; ///< K_t'/K_t [1]
  };
  MismatchEffect mismatch_effect(const ValveDescription &valve, double temperature, const MagneticMismatch &mismatch);
} // namespace servodrift
