#include "system/valve_equations.h"

#include "common/error.h"
#include "common/thermal_laws.h"
#include "common/units.h"

#include <algorithm>
#include <cmath>

namespace servodrift::system
{
  ValveEquations::ValveEquations(const ValveDescription &valve, const StageFunctions &functions, double temperature,
                                 const Offsets &offsets)
    : f(functions)
    , offsets_(offsets)
    , T(temperature)
  {
    const double T0 = valve.operating.reference_temperature;
    const auto &s = valve.spool;
    const auto &tm = valve.torque_motor;
    const laws::Oil oil(valve.fluid, T0);
    voltage_drive_ = tm.voltage_drive;
    p_s = valve.operating.supply_pressure;
    p_r = valve.operating.return_pressure;
    r = valve.armature.pivot_to_nozzle_distance;
    x0 = laws::pilot_stage_geometry(valve.pilot, valve.armature, valve.expansion, T, T0).null_gap;
    K_a = f.stiffness(T);
    J_a = valve.armature.inertia;
    B_a = valve.armature.damping; // constant in temperature (C14)
    contact_stiffness = valve.armature.nozzle_contact_stiffness;
    contact_damping = 2 * valve.armature.nozzle_contact_damping_ratio * std::sqrt(contact_stiffness * J_a / (r * r));
    orifice_dp_max = f.orifice_conductance.axis(1).back();
    nozzle_dp_max = f.nozzle_conductance.axis(2).back();
    gap_max = f.nozzle_conductance.axis(1).back();

    const auto areas = laws::spool_geometry(s, valve.expansion, T, T0);
    A_v = areas.control_area;
    A_fb = areas.feedback_area;
    V_0 = valve.pilot.control_cavity_volume;
    beta = oil.effective_bulk_modulus(T);
    V_B = s.brake_port == SpoolParameters::BrakePort::blocked_port ? s.port_volume : s.brake_volume;
    m_v = s.mass;
    rho = oil.density(T).value;
    nu = oil.kinematic_viscosity(T).value;
    const double mu = rho * nu;
    B_v = mu * units::pi * s.control_diameter * s.land_length / s.radial_clearance; // 2.7, C14
    k_s = s.spring_rate;
    F_s0 = s.spring_preload;
    W = s.area_gradient;
    x_ov = s.overlap;
    stroke = s.stroke_limit;
    C_dv = s.discharge_coefficient;
    jet_cosine = std::cos(s.jet_angle * units::degree);
    stop_stiffness = s.stop_stiffness;
    stop_damping = 2 * s.stop_damping_ratio * std::sqrt(stop_stiffness * m_v);
    // E36 lap leakage pi d_v c_r^3 dp/(12 mu L): the coefficient of dp/L
    leak_coefficient = units::pi * s.control_diameter * std::pow(s.radial_clearance, 3) / (12 * mu);
    minimum_leak_length = s.minimum_leak_length;
    transition_number = s.laminar_transition_number;

    coil_resistance = laws::coil_resistance(tm, T);
    L_c = laws::coil_inductance(tm);

    // The asymmetric valve (issue 25; doc/method.md "Asymmetric valve"): the tables hold the
    // nominal geometry; a side's own bores enter through the closed forms at that side's geometry.
    pilot_tables = {&f, &f};
    for (const Side side : {left, right})
      {
        const SideDeviations &d = offsets_.sides[side];
        side_gap[side] = x0 + d.null_gap;
        orifice_factor[side] = d.orifice_discharge_factor;
        nozzle_factor[side] = d.nozzle_discharge_factor;
        orifice_deviation[side] = d.orifice_diameter;
        nozzle_deviation[side] = d.nozzle_diameter;
        orifice_bore_deviates[side] = d.orifice_diameter != 0;
        nozzle_bore_deviates[side] = d.nozzle_diameter != 0;
        side_deviates[side] = orifice_bore_deviates[side] || nozzle_bore_deviates[side] ||
                              d.orifice_discharge_factor != 1 || d.nozzle_discharge_factor != 1;
        if (!side_deviates[side])
          continue;
        if (!nominal_forms)
          nominal_forms = std::make_shared<const PilotClosedForms>(valve, T);
        side_forms[side] = nominal_forms;
        if (orifice_bore_deviates[side] || nozzle_bore_deviates[side])
          {
            ValveDescription built = valve;
            built.pilot.fixed_orifice_diameter += d.orifice_diameter;
            built.pilot.nozzle_diameter += d.nozzle_diameter;
            side_forms[side] = std::make_shared<const PilotClosedForms>(built, T);
          }
      }
    magnetic_null_ = offsets_.magnetic_null;
    motor_mismatch = offsets_.magnetic.any();
    if (motor_mismatch)
      {
        const MismatchEffect e = mismatch_effect(valve, T, offsets_.magnetic);
        magnetic_null_ += e.null_angle;
        magnetic_spring_ratio = e.magnetic_spring_ratio;
        torque_constant_ratio = e.torque_constant_ratio;
      }
  }

  // --- armature and flapper --------------------------------------------------------------------

  double ValveEquations::motor_torque(double angle, double current) const
  {
    try
      {
        const double a = angle - magnetic_null_;
        if (!motor_mismatch)
          return f.torque(T, a, current);
        // the mismatched motor: the table's magnetic-spring part T(a, 0) and current part
        // T(a, i) - T(a, 0), each scaled as E3 scales K_m and K_t at this temperature
        const double spring = f.torque(T, a, 0.0);
        return magnetic_spring_ratio * spring + torque_constant_ratio * (f.torque(T, a, current) - spring);
      }
    catch (const TableRangeError &e)
      {
        throw TableRangeError(std::string(e.what()) +
                              " (extend `Sweeps/Motor angles' or `Sweeps/Motor currents' to cover the motion)");
      }
  }

  double ValveEquations::torque_per_current(double angle, double current) const
  {
    // central difference inside the table's current range (one-sided at its ends)
    const auto &currents = f.torque.axis(2);
    const double h = 1e-4 * (currents.back() - currents.front());
    const double lo = std::max(current - h, currents.front()), hi = std::min(current + h, currents.back());
    return (motor_torque(angle, hi) - motor_torque(angle, lo)) / (hi - lo);
  }

  double ValveEquations::nozzle_contact_torque(double angle, double angular_velocity) const
  {
    // Kelvin-Voigt stop at each nozzle tip, active only while the flapper is past it, never pulling
    const double x_f = flapper_displacement(angle), v_f = r * angular_velocity;
    double torque = 0;
    if (const double depth = x_f - side_gap[left]; depth > 0) // into the left nozzle: pushed towards -x_f
      torque -= r * std::max(0.0, contact_stiffness * depth + contact_damping * v_f);
    if (const double depth = -side_gap[right] - x_f; depth > 0) // into the right nozzle: pushed towards +x_f
      torque += r * std::max(0.0, contact_stiffness * depth - contact_damping * v_f);
    return torque;
  }

  double ValveEquations::net_torque(double angle, double angular_velocity, double p_L, double p_R, double current) const
  {
    const auto [left_gap, right_gap] = gaps(angle);
    // E29 with the offsets of E39: K_t i + K_m theta (the table), -K_a (theta - theta_s), -r dF_f
    return motor_torque(angle, current) - K_a * (angle - offsets_.spring_tube_rest_angle) -
           r * (flapper_force(left, left_gap, p_L - p_r) - flapper_force(right, right_gap, p_R - p_r)) +
           nozzle_contact_torque(angle, angular_velocity);
  }

  // --- pilot stage -----------------------------------------------------------------------------

  std::array<double, 2> ValveEquations::gaps_at(double x_f) const
  {
    return {std::max(0.0, side_gap[left] - x_f), std::max(0.0, side_gap[right] + x_f)};
  }

  namespace
  {
    // The closed forms' ratio at dp -> 0 or h -> 0 is their laminar limit (0/0 at the limit
    // itself): evaluated at these floors, deep in the laminar range of every bore.
    constexpr double ratio_pressure_floor = 1.0; // [Pa]
    constexpr double ratio_gap_floor = 1e-8;     // [m]
  } // namespace

  namespace
  {
    /// exp(ln ratio(x) deviation/step): the bore tables' ratio carried log-linearly to a side's
    /// deviation, the query held within their few points (they need not span the flow tables)
    template <typename... X>
    double bore_power(const GridFunction &log_ratio, double deviation, double step, X... x)
    {
      unsigned int k = 0;
      const auto clamped = [&](double value) {
        const auto &axis = log_ratio.axis(k++);
        return std::clamp(value, axis.front(), axis.back());
      };
      const double at[] = {clamped(x)...};
      return std::exp(log_ratio.value(at) * deviation / step);
    }
  } // namespace

  double ValveEquations::orifice_bore_ratio(Side side, double a) const
  {
    if (!orifice_bore_deviates[side])
      return 1;
    if (const auto &bore = pilot_tables[side]->orifice_bore)
      return bore_power(bore->log_flow_ratio, orifice_deviation[side], bore->step, T, a);
    const double dp = std::max(a, ratio_pressure_floor);
    return side_forms[side]->fixed_orifice(dp).flow_rate / nominal_forms->fixed_orifice(dp).flow_rate; // E21
  }

  double ValveEquations::nozzle_bore_ratio(Side side, double h, double a) const
  {
    if (!nozzle_bore_deviates[side])
      return 1;
    if (const auto &bore = pilot_tables[side]->nozzle_bore)
      return bore_power(bore->log_flow_ratio, nozzle_deviation[side], bore->step, T, h, a);
    const double dp = std::max(a, ratio_pressure_floor), gap = std::max(h, ratio_gap_floor);
    return side_forms[side]->nozzle(gap, dp).flow_rate / nominal_forms->nozzle(gap, dp).flow_rate; // E22
  }

  std::optional<double> ValveEquations::force_bore_ratio(Side side, double h, double a) const
  {
    const auto &bore = pilot_tables[side]->nozzle_bore;
    if (!nozzle_bore_deviates[side] || !bore)
      return std::nullopt;
    return bore_power(*bore->log_force_ratio, nozzle_deviation[side], bore->step, T, h, a);
  }

  // The tables give Q/sqrt(dp), which tends to 0 in the laminar limit dp -> 0, so Q = c(dp) sqrt(dp)
  // is a signed square root with a laminar region (E20) of the table's own making. Beyond the
  // tabulated pressure range (only in a transient) C_d is held at its last value, and flagged.
  double ValveEquations::tabulated_orifice_flow(Side side, double a) const
  {
    if (a > orifice_dp_max)
      table_exceeded = true;
    return pilot_tables[side]->orifice_conductance(T, std::min(a, orifice_dp_max)) * std::sqrt(a);
  }

  double ValveEquations::orifice_flow(Side side, double dp) const
  {
    const double a = std::abs(dp);
    return std::copysign(orifice_factor[side] * orifice_bore_ratio(side, a) * tabulated_orifice_flow(side, a), dp); // E31
  }

  double ValveEquations::tabulated_nozzle_flow(Side side, double gap, double a) const
  {
    if (a > nozzle_dp_max)
      table_exceeded = true;
    const double h = std::clamp(gap, 0.0, gap_max);
    return pilot_tables[side]->nozzle_conductance(T, h, std::min(a, nozzle_dp_max)) * std::sqrt(a);
  }

  double ValveEquations::nozzle_flow(Side side, double gap, double dp) const
  {
    const double a = std::abs(dp);
    return std::copysign(nozzle_factor[side] * nozzle_bore_ratio(side, gap, a) * tabulated_nozzle_flow(side, gap, a), dp); // E32
  }

  double ValveEquations::flapper_force(Side side, double gap, double dp) const
  {
    // E23 / table; odd in dp (a reversed jet pulls), proportional to dp beyond the table
    const GridFunction &table = pilot_tables[side]->flapper_force;
    const double a = std::abs(dp), h = std::clamp(gap, 0.0, gap_max);
    double force = a <= nozzle_dp_max ? table(T, h, a) : table(T, h, nozzle_dp_max) * a / nozzle_dp_max;
    if (side_deviates[side])
      {
        // to this side's bore: by the bore table's force ratio, or by E23's change from the tables'
        // bore and flow to the side's (the bore pressure on its own projection, the momentum of its
        // own flow); then the discharge factor by E23's momentum change of the flow it scales
        const double tabulated = tabulated_nozzle_flow(side, gap, a);
        const double at_bore = nozzle_bore_ratio(side, gap, a) * tabulated;
        if (const auto ratio = force_bore_ratio(side, gap, a))
          force *= *ratio;
        else
          force += side_forms[side]->jet_force(a, at_bore) - nominal_forms->jet_force(a, tabulated);
        force += side_forms[side]->jet_force(a, nozzle_factor[side] * at_bore) - side_forms[side]->jet_force(a, at_bore);
      }
    return std::copysign(force, dp);
  }

  bool ValveEquations::symmetric_bridge() const
  {
    const auto &[l, r] = offsets_.sides;
    return l.orifice_diameter == r.orifice_diameter && l.nozzle_diameter == r.nozzle_diameter &&
           l.null_gap == r.null_gap && l.orifice_discharge_factor == r.orifice_discharge_factor &&
           l.nozzle_discharge_factor == r.nozzle_discharge_factor && pilot_tables[left] == pilot_tables[right];
  }

  double ValveEquations::cavity_inflow(Side side, double gap, double pressure, double volume_rate) const
  {
    return orifice_flow(side, p_s - pressure) - nozzle_flow(side, gap, pressure - p_r) - volume_rate; // E33
  }

  // --- spool stage -----------------------------------------------------------------------------

  std::array<double, 2> ValveEquations::edge(double opening, double dp) const
  {
    // Laminar leakage across the land, pi d_v c_r^3 dp/(12 mu L), over the leak length L = -opening
    // while overlapped, floored so that it stays finite at and past the edge (E36, C14). The floor
    // is a smooth maximum, L_min + L_min ln(1 + exp((L - L_min)/L_min)), so that the right-hand side
    // stays smooth through the lap edge, which the spool crosses in most large-signal responses.
    const double excess = (-opening - minimum_leak_length) / minimum_leak_length;
    const double leak_length =
      minimum_leak_length * (1 + (excess > 30 ? excess : std::log1p(std::exp(excess))));
    double flow = leak_coefficient / leak_length * dp;
    double force = 0;
    if (opening > 0)
      {
        // E36 orifice with E20's tanh blend: lambda = D_h v/nu, D_h = 2 x opening (annular slot)
        const double area = W * opening, velocity = std::sqrt(2 * std::abs(dp) / rho);
        const double C_d = C_dv * std::tanh(2 * (2 * opening * velocity / nu) / transition_number);
        flow += std::copysign(C_d * area * velocity, dp);
        force = 2 * C_d * area * std::abs(dp) * jet_cosine; // E35: rho Q v cos(jet), velocity coefficient 1
      }
    return {flow, force};
  }

  MeteringEdges ValveEquations::metering(double x_v, double p_B) const
  {
    const auto supply = edge(x_v - x_ov, p_s - p_B);  // opens for x_v > x_ov
    const auto drain = edge(-x_v - x_ov, p_B - p_r);  // opens for x_v < -x_ov
    return {supply[0], drain[0], supply[1], drain[1]};
  }

  double ValveEquations::brake_inflow(double x_v, double p_B) const
  {
    const MeteringEdges m = metering(x_v, p_B);
    return m.supply_flow - m.return_flow; // E36, E37 with Q_load = 0 (blocked brake)
  }

  double ValveEquations::spool_net_force(double x_v, double v_v, double dp_c, double p_B) const
  {
    const MeteringEdges m = metering(x_v, p_B);
    // stroke stops: Kelvin-Voigt, only past the limit, never pulling
    double stop = 0;
    if (const double depth = x_v - stroke; depth > 0)
      stop = std::max(0.0, stop_stiffness * depth + stop_damping * v_v);
    else if (const double depth = -stroke - x_v; depth > 0)
      stop = -std::max(0.0, stop_stiffness * depth - stop_damping * v_v);
    // E35: A_v (p_L - p_R) - A_fb (p_B - p_r) - k_s x_v - F_s0 - F_s (flow forces close the open edge)
    return A_v * dp_c - A_fb * (p_B - p_r) - k_s * x_v - F_s0 - m.supply_force + m.return_force - stop;
  }

  // --- the right-hand side -----------------------------------------------------------------------

  ValveState ValveEquations::rates(const ValveState &s, const ValveInput &input) const
  {
    const double i = current(s, input);
    const auto [left_gap, right_gap] = gaps(s.angle);
    const double volume_rate = A_v * s.spool_velocity;
    ValveState d;
    d.angle = s.angular_velocity;
    // E29: J_a theta'' = net torque - B_a theta'
    d.angular_velocity =
      (net_torque(s.angle, s.angular_velocity, s.left_pressure, s.right_pressure, i) - B_a * s.angular_velocity) / J_a;
    // E33: the spool end enlarges the left cavity and shrinks the right one as it moves to +x
    d.left_pressure =
      beta / (V_0 + A_v * s.spool_displacement) * cavity_inflow(left, left_gap, s.left_pressure, volume_rate);
    d.right_pressure =
      beta / (V_0 - A_v * s.spool_displacement) * cavity_inflow(right, right_gap, s.right_pressure, -volume_rate);
    d.spool_displacement = s.spool_velocity;
    // E35: m_v x_v'' = net force - B_v(T) x_v'
    d.spool_velocity = (spool_net_force(s.spool_displacement, s.spool_velocity, s.left_pressure - s.right_pressure,
                                        s.brake_pressure) -
                        B_v * s.spool_velocity) /
                       m_v;
    d.brake_pressure = beta / V_B * brake_inflow(s.spool_displacement, s.brake_pressure); // E37
    // 1.20: L_c i' = u - R_c(T) i - k_e theta', k_e = dT_em/di by reciprocity
    d.coil_current = voltage_drive_ ? (input.voltage - coil_resistance * i -
                                       torque_per_current(s.angle, i) * s.angular_velocity) /
                                        L_c :
                                      0.0;
    return d;
  }
} // namespace servodrift::system
