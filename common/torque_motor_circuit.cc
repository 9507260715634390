#include "common/torque_motor_circuit.h"

#include "common/thermal_laws.h"
#include "common/units.h"

#include <Eigen/Dense>

#include <cmath>
#include <stdexcept>

namespace servodrift
{
  using units::mu0;

  TorqueMotorCircuit::TorqueMotorCircuit(const ValveDescription &valve, double T, const MagneticMismatch &mismatch)
  {
    const auto &m = valve.torque_motor;
    const double T0 = valve.operating.reference_temperature;
    const auto g = laws::torque_motor_geometry(m, valve.expansion, T, T0); // E6, E7 and thermal growth
    a = g.pivot_to_pole_distance;
    w_p = g.pole_face_width;
    l_p = g.pole_face_length;
    g12 = g.lower_gap;
    g34 = g.upper_gap;
    lower_mismatch = mismatch.lower_gap_mismatch;
    fringing = m.fringing_expanded_area;
    // E8: M = B_r(T) l_m(T)/(mu0 mu_rm), linear recoil line
    mmf = laws::remanence(m, T, T0) * g.magnet_length / (mu0 * m.recoil_permeability);
    // Magnets in parallel with equal internal reluctance: their Norton sum has the mean MMF.
    if (mismatch.left_remanence != 0 || mismatch.right_remanence != 0)
      mmf *= 1 + 0.5 * (mismatch.left_remanence + mismatch.right_remanence);
    // E2: R_m = l_m/(mu0 mu_rm A_m,tot), magnets in parallel
    R_m = g.magnet_length / (mu0 * m.recoil_permeability * m.number_of_magnets * g.magnet_area);
    // Lumped reluctances of model.md 2.2 without a thermal law: 1.3 lets the gaps, a, A_g and l_m
    // grow, not these. (Scaling R_l as 1/length with the pole pieces would move the 40 -> 120 degC
    // torque trend by -0.06 %, against C2's independent check; see doc/validation.md.)
    R_l = m.leakage_reluctance;
    R_c = m.pole_piece_reluctance;
    R_a = m.armature_reluctance;
    effective_turns = m.effective_turns();
  }

  double TorqueMotorCircuit::gap_area(double g) const
  {
    // E2 (optional fringing: A_g,eff = (w_p + g)(l_p + g))
    return fringing ? (w_p + g) * (l_p + g) : w_p * l_p;
  }

  double TorqueMotorCircuit::gap_reluctance_at_null() const
  {
    const double g = mean_gap();
    return g / (mu0 * gap_area(g));
  }

  CircuitSolution TorqueMotorCircuit::solve(double theta, double current) const
  {
    CircuitSolution s;
    const double x = a * theta; // E2: gaps 1 and 4 close for theta > 0
    s.gap = {g12 - x, g12 + x, g34 + x, g34 - x};
    if (lower_mismatch != 0)
      s.gap[0] += 0.5 * lower_mismatch, s.gap[1] -= 0.5 * lower_mismatch;
    std::array<double, 4> R;
    for (int k = 0; k < 4; ++k)
      {
        if (!(s.gap[k] > 0))
          throw std::runtime_error("torque motor circuit: gap " + std::to_string(k + 1) + " closed at theta = " +
                                   std::to_string(theta) + " rad");
        R[k] = s.gap[k] / (mu0 * gap_area(s.gap[k])); // E2
      }
    const double NI = effective_turns * current; // net control MMF (D7)

    // E3: four clockwise meshes (magnet/leakage, leakage/left path, upper triangle, lower triangle)
    Eigen::Matrix4d A;
    A << R_m + R_c + R_l, -R_l, 0, 0,            //
      -R_l, R_l + R[2] + R[0], -R[2], -R[0],     //
      0, -R[2], R[2] + R[3] + R_a, -R_a,         //
      0, -R[0], -R_a, R[0] + R[1] + R_a;
    const Eigen::Vector4d rhs(mmf, 0, NI, -NI);
    const Eigen::Vector4d phi = A.partialPivLu().solve(rhs);

    s.gap_flux = {phi(1) - phi(3), phi(3), phi(1) - phi(2), phi(2)};
    s.magnet_flux = phi(0);
    s.leakage_flux = phi(0) - phi(1);
    s.armature_flux = phi(3) - phi(2);
    // E9: F_k = phi_k^2/(2 mu0 A_g);  E10: T = a (F_1 - F_2 - F_3 + F_4)
    std::array<double, 4> F;
    for (int k = 0; k < 4; ++k)
      F[k] = s.gap_flux[k] * s.gap_flux[k] / (2 * mu0 * gap_area(s.gap[k]));
    s.torque = a * (F[0] - F[1] - F[2] + F[3]);
    return s;
  }

  MismatchEffect mismatch_effect(const ValveDescription &valve, double T, const MagneticMismatch &mismatch)
  {
    const TorqueMotorCircuit nominal(valve, T), built(valve, T, mismatch);
    // central differences over steps far below the gaps and the rated current, where E3 is smooth
    const double h = 1e-4 * nominal.mean_gap() / nominal.pivot_to_pole_distance();
    const double di = 1e-3 * valve.operating.rated_current;
    const auto spring = [h](const TorqueMotorCircuit &c, double theta) {
      return (c.torque(theta + h, 0) - c.torque(theta - h, 0)) / (2 * h);
    };
    const auto constant = [di](const TorqueMotorCircuit &c, double theta) {
      return (c.torque(theta, di) - c.torque(theta, -di)) / (2 * di);
    };
    MismatchEffect e;
    // Newton on T(theta, 0) = 0 from theta = 0: the torque is smooth and nearly linear over the
    // micro-radians a mismatch moves the null, so a few steps reach round-off.
    for (int k = 0; k < 8; ++k)
      {
        const double step = built.torque(e.null_angle, 0) / spring(built, e.null_angle);
        e.null_angle -= step;
        if (std::abs(step) < 1e-15)
          break;
      }
    e.magnetic_spring_ratio = spring(built, e.null_angle) / spring(nominal, 0);
    e.torque_constant_ratio = constant(built, e.null_angle) / constant(nominal, 0);
    return e;
  }
} // namespace servodrift
