#include "system/dynamic_checks.h"

#include "common/table_coefficients.h"
#include "common/units.h"

#include <cmath>

namespace servodrift::system
{
  namespace
  {
    double hertz(double omega)
    {
      return omega / (2 * units::pi);
    }
  } // namespace

  DynamicChecks dynamic_checks(const ValveModel &model, const ValveDynamics &dynamics)
  {
    const ValveEquations &eq = dynamics.equations();
    const double T = eq.temperature(), r = eq.pivot_to_nozzle_distance(), J = eq.inertia();
    DynamicChecks c;

    // model.md 2.5 / 1.12: the net stiffness K_a - K_m + r^2 K_f at the null
    const double K_m = torque_motor_coefficients(model.functions().torque, T).magnetic_spring;
    const double K_f = model.flow_force_stiffness(T);
    c.armature_closed_form = hertz(std::sqrt((eq.spring_stiffness() - K_m + r * r * K_f) / J));

    const OperatingPoint null = model.solve(eq, dynamics.steady_current(0.0));
    const Linearisation l = linearise(dynamics, null.state(), 0.0);
    // armature (theta, omega) with the pressures eliminated: p' = 0 gives p = -A_pp^-1 A_pa (theta, omega)
    const Eigen::MatrixXd A_aa = l.A.block(0, 0, 2, 2), A_ap = l.A.block(0, 2, 2, 2);
    const Eigen::MatrixXd A_pa = l.A.block(2, 0, 2, 2), A_pp = l.A.block(2, 2, 2, 2);
    const Eigen::MatrixXd reduced = A_aa - A_ap * A_pp.partialPivLu().solve(A_pa);
    c.armature_blocked = hertz(std::sqrt(-reduced(1, 0))); // omega' = -(K_eff/J) theta - ...
    // armature and compressible cavities, spool held: the complex pair of the 4 x 4 block
    const Eigen::MatrixXd block = l.A.topLeftCorner(4, 4);
    for (const auto &lambda : eigenvalues(block, {l.scales.begin(), l.scales.begin() + 4}))
      if (lambda.imag() > 0)
        c.armature_compressible = hertz(std::abs(lambda));
    double most = -1;
    for (const Mode &m : modes(l))
      if (m.participation[0] > most)
        {
          most = m.participation[0];
          c.armature_coupled = m.natural_frequency;
        }

    // the control-cavity pressure: dp/dt = (beta_e/V_0) (Q_0(p_s - p) - Q_N(p - p_r)) at a held flapper
    const double p = null.bridge.left_pressure, gap = null.bridge.left_gap;
    const double dp_0 = eq.supply_pressure() - p, dp_N = p - eq.return_pressure();
    const double Q = eq.orifice_flow(left, dp_0);
    // the left cavity's volume where the spool sits (E33: V_0 + A_v x_v)
    const double V = eq.control_cavity_volume() + eq.control_area() * null.spool.displacement, beta = eq.bulk_modulus();
    c.pressure_time_constant_closed_form = V / (beta * (Q / (2 * dp_0) + Q / (2 * dp_N)));
    const double h = 1e-6 * (eq.supply_pressure() - eq.return_pressure());
    const double slope = -(eq.cavity_inflow(left, gap, p + h, 0) - eq.cavity_inflow(left, gap, p - h, 0)) / (2 * h);
    c.pressure_time_constant_tables = V / (beta * slope);
    c.pressure_time_constant = -1 / l.A(2, 2);
    return c;
  }
} // namespace servodrift::system
