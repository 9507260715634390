#include "magnetics/reduced_order_circuit.h"

#include "common/thermal_laws.h"
#include "common/units.h"

#include <Eigen/Dense>

#include <stdexcept>

namespace servodrift::magnetics
{
  using units::mu0;

  ReducedOrderCircuit::ReducedOrderCircuit(const ValveDescription &valve, double T)
  {
    const auto &m = valve.torque_motor;
    const double T0 = valve.operating.reference_temperature;
    const auto g = laws::torque_motor_geometry(m, valve.expansion, T, T0); // E6, E7 and thermal growth
    a = g.pivot_to_pole_distance;
    w_p = g.pole_face_width;
    l_p = g.pole_face_length;
    g12 = g.lower_gap;
    g34 = g.upper_gap;
    fringing = m.fringing_expanded_area;
    // E8: M = B_r(T) l_m(T)/(mu0 mu_rm), linear recoil line
    mmf = laws::remanence(m, T, T0) * g.magnet_length / (mu0 * m.recoil_permeability);
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

  double ReducedOrderCircuit::gap_area(double g) const
  {
    // E2 (optional fringing: A_g,eff = (w_p + g)(l_p + g))
    return fringing ? (w_p + g) * (l_p + g) : w_p * l_p;
  }

  double ReducedOrderCircuit::gap_reluctance_at_null() const
  {
    const double g = mean_gap();
    return g / (mu0 * gap_area(g));
  }

  CircuitSolution ReducedOrderCircuit::solve(double theta, double current) const
  {
    CircuitSolution s;
    const double x = a * theta; // E2: gaps 1 and 4 close for theta > 0
    s.gap = {g12 - x, g12 + x, g34 + x, g34 - x};
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
} // namespace servodrift::magnetics
