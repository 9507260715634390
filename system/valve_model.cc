#include "system/valve_model.h"

#include "common/error.h"
#include "common/pilot_bridge.h"
#include "common/root_finding.h"
#include "common/thermal_laws.h"

#include <algorithm>
#include <cmath>

namespace servodrift::system
{
  const char *to_string(FlapperState s)
  {
    switch (s)
      {
        case FlapperState::free: return "free";
        case FlapperState::on_left_nozzle: return "on-left-nozzle";
        case FlapperState::on_right_nozzle: return "on-right-nozzle";
      }
    return "?";
  }

  const char *to_string(SpoolState s)
  {
    switch (s)
      {
        case SpoolState::on_negative_stop: return "on-negative-stop";
        case SpoolState::vented: return "vented";
        case SpoolState::regulating: return "regulating";
        case SpoolState::at_supply: return "at-supply";
        case SpoolState::on_positive_stop: return "on-positive-stop";
      }
    return "?";
  }

  ValveModel::ValveModel(const ValveDescription &valve_, const StageTables &tables)
    : valve(valve_)
    , f(tables)
    , p_s(valve_.operating.supply_pressure)
    , p_r(valve_.operating.return_pressure)
    , r(valve_.armature.pivot_to_nozzle_distance)
  {}

  double ValveModel::null_gap(double T) const
  {
    return laws::pilot_stage_geometry(valve.pilot, valve.armature, valve.expansion, T,
                                      valve.operating.reference_temperature)
      .null_gap;
  }

  BridgeState ValveModel::bridge(double T, double x_f) const
  {
    BridgeState b;
    const double x0 = null_gap(T);
    // A gap that is zero up to rounding (flapper on a nozzle) is exactly zero.
    b.left_gap = std::max(0.0, x0 - x_f);
    b.right_gap = std::max(0.0, x0 + x_f);
    const auto orifice_flow = [&](double dp) { return f.orifice_conductance(T, dp) * std::sqrt(dp); }; // E31
    auto half_bridge = [&](double gap, double &pressure, double &flow, double &force) {
      const auto nozzle_flow = [&](double dp) { return f.nozzle_conductance(T, gap, dp) * std::sqrt(dp); }; // E32
      pressure = bridge_pressure(orifice_flow, nozzle_flow, p_s, p_r);
      flow = nozzle_flow(pressure - p_r);
      force = f.flapper_force(T, gap, pressure - p_r);
    };
    half_bridge(b.left_gap, b.left_pressure, b.left_flow, b.left_force);
    half_bridge(b.right_gap, b.right_pressure, b.right_flow, b.right_force);
    return b;
  }

  SpoolSolution ValveModel::spool(double T, double dp_c) const
  {
    // E35, static, brake port blocked: A_v dp_c - A_fb (p_B - p_r) - k_s x_v - F_s0 = 0. The steady
    // flow force vanishes: an open edge of a blocked port carries no pressure drop. p_B(x_v) follows
    // from Q_B = 0 (E36): vented (p_B = p_r) below -x_ov, open to supply (p_B = p_s) above x_ov, and
    // in the lap the laminar leakage across the two overlaps (conductance ~ 1/overlap length, same
    // clearance) divides the supply: p_B - p_r = (p_s - p_r)(x_ov + x_v)/(2 x_ov).
    const auto &s = valve.spool;
    const auto areas = laws::spool_geometry(s, valve.expansion, T, valve.operating.reference_temperature);
    const double A_v = areas.control_area, A_fb = areas.feedback_area;
    const double x_ov = s.overlap, k = s.spring_rate, stroke = s.stroke_limit, span = p_s - p_r;
    const double drive = A_v * dp_c - s.spring_preload;
    const auto residual = [&](double x, double p_B) { return drive - A_fb * (p_B - p_r) - k * x; };
    const auto lap_pressure = [&](double x) { return p_r + span * (x_ov + x) / (2 * x_ov); };

    SpoolSolution out;
    if (residual(-x_ov, p_r) <= 0) // vented
      {
        out = {k > 0 ? drive / k : -stroke, p_r, SpoolState::vented};
        if (out.displacement <= -stroke)
          out = {-stroke, p_r, SpoolState::on_negative_stop};
      }
    else if (residual(x_ov, p_s) >= 0) // open to supply
      {
        out = {k > 0 ? (drive - A_fb * span) / k : stroke, p_s, SpoolState::at_supply};
        if (out.displacement >= stroke)
          out = {stroke, p_s, SpoolState::on_positive_stop};
      }
    else // regulating in the lap: residual linear in x
      {
        const double x = (drive - 0.5 * A_fb * span) / (k + A_fb * span / (2 * x_ov));
        out = {x, lap_pressure(x), SpoolState::regulating};
      }
    return out;
  }

  OperatingPoint ValveModel::solve(double T, double i, const Offsets &o) const
  {
    const double K_a = f.stiffness(T);
    const double x0 = null_gap(T);
    // E29 static with E39: motor torque - spring-tube torque - flapper torque = 0
    BridgeState last;
    const auto net_torque = [&](double theta) {
      last = bridge(T, r * theta - o.hydraulic_null);
      return f.torque(T, theta - o.magnetic_null, i) - K_a * (theta - o.spring_tube_rest_angle) -
             r * (last.left_force - last.right_force);
    };

    // Bracket: the nozzle contacts (x_f = -+ x0), narrowed to what the tables cover.
    double lo = (o.hydraulic_null - x0) / r, hi = (o.hydraulic_null + x0) / r;
    bool lo_is_contact = true, hi_is_contact = true;
    auto narrow = [&](double table_lo, double table_hi) {
      if (table_lo > lo)
        lo = table_lo, lo_is_contact = false;
      if (table_hi < hi)
        hi = table_hi, hi_is_contact = false;
    };
    const auto &angles = f.torque.axis(1);
    narrow(o.magnetic_null + angles.front(), o.magnetic_null + angles.back());
    const auto &gaps = f.nozzle_conductance.axis(1);
    // left gap x0 - x_f and right gap x0 + x_f both within [gap_min, gap_max]
    const double x_f_lo = std::max(x0 - gaps.back(), gaps.front() - x0);
    const double x_f_hi = std::min(x0 - gaps.front(), gaps.back() - x0);
    narrow((x_f_lo + o.hydraulic_null) / r, (x_f_hi + o.hydraulic_null) / r);
    if (!(lo < hi))
      throw TableRangeError("the tables leave no armature angle for the flapper at " + format_number(T) +
                            " degC (torque_motor angles and nozzle_flapper gaps do not overlap the flapper travel)");

    OperatingPoint op;
    op.temperature = T;
    op.current = i;
    const double n_lo = net_torque(lo), n_hi = net_torque(hi);
    auto table_edge = [&](const char *side) {
      return TableRangeError(std::string("the static solution at ") + format_number(T) + " degC, i = " +
                             format_number(i) + " A lies beyond the " + side +
                             " end of the tables' angle/gap range (extend `Sweeps/Motor angles' or "
                             "`Sweeps/Gap fractions')");
    };
    if (n_hi >= 0)
      {
        if (!hi_is_contact)
          throw table_edge("upper");
        op.angle = hi;
        op.flapper = FlapperState::on_left_nozzle;
      }
    else if (n_lo <= 0)
      {
        if (!lo_is_contact)
          throw table_edge("lower");
        op.angle = lo;
        op.flapper = FlapperState::on_right_nozzle;
      }
    else
      {
        op.angle = find_root(net_torque, lo, hi, n_lo, n_hi, 1e-13 * (hi - lo) + 1e-18, "torque balance (E29)");
        op.flapper = FlapperState::free;
      }
    op.flapper_displacement = r * op.angle - o.hydraulic_null;
    op.bridge = bridge(T, op.flapper_displacement);
    op.spool = spool(T, op.control_pressure_difference());
    return op;
  }

  double ValveModel::nulling_hydraulic_null(const Offsets &o) const
  {
    // With the flapper centred the two jets balance, so the armature obeys the motor and the spring
    // tube alone: T_em(T0, theta - theta_m, 0) = K_a (theta - theta_s). x_n = r theta centres it.
    const double T0 = valve.operating.reference_temperature;
    const double K_a = f.stiffness(T0);
    const auto balance = [&](double theta) {
      return f.torque(T0, theta - o.magnetic_null, 0.0) - K_a * (theta - o.spring_tube_rest_angle);
    };
    const auto &angles = f.torque.axis(1);
    const double lo = o.magnetic_null + angles.front(), hi = o.magnetic_null + angles.back();
    const double b_lo = balance(lo), b_hi = balance(hi);
    if (!(b_lo > 0 && b_hi < 0))
      throw TableRangeError("nulling at the reference temperature: K_a (theta - theta_s) = T_em(theta - theta_m) "
                            "has no root within the torque_motor table's angles (extend `Sweeps/Motor angles'; "
                            "a root also needs K_a > K_m)");
    return r * find_root(balance, lo, hi, b_lo, b_hi, 1e-13 * (hi - lo), "null adjustment at T0");
  }

  std::optional<double> ValveModel::null_shift_current(double T, const Offsets &o) const
  {
    // Flapper centred (x_f = 0, p_L = p_R): theta = x_n/r and the jets balance.
    const double theta = o.hydraulic_null / r;
    const double a = theta - o.magnetic_null;
    const auto &angles = f.torque.axis(1);
    if (a < angles.front() || a > angles.back())
      return std::nullopt;
    const double K_a = f.stiffness(T);
    const auto balance = [&](double i) { return f.torque(T, a, i) - K_a * (theta - o.spring_tube_rest_angle); };
    const auto &currents = f.torque.axis(2);
    const double b_lo = balance(currents.front()), b_hi = balance(currents.back());
    if ((b_lo > 0) == (b_hi > 0) && b_lo != 0 && b_hi != 0)
      return std::nullopt;
    return find_root(balance, currents.front(), currents.back(), b_lo, b_hi, 1e-15, "null-shift current");
  }

  Offsets ValveModel::offsets_for_deviation(double theta_d) const
  {
    const auto &base = valve.offsets;
    Offsets o{base.spring_tube_rest_angle, base.magnetic_null, base.hydraulic_null};
    switch (base.deviation_target)
      {
        case OffsetParameters::Target::magnetic_null: o.magnetic_null += theta_d; break;
        case OffsetParameters::Target::spring_tube_rest_angle: o.spring_tube_rest_angle -= theta_d; break; // E38
        case OffsetParameters::Target::hydraulic_null: o.hydraulic_null -= r * theta_d; break;
      }
    if (base.nulling == OffsetParameters::Nulling::nulled_at_reference)
      o.hydraulic_null = nulling_hydraulic_null(o);
    return o;
  }

  double ValveModel::flow_force_stiffness(double T) const
  {
    // E24: dF_f = F_L - F_R ~ K_f x_f (restoring: it pushes the flapper away from the closer nozzle);
    // central differences over +-1e-3 x0
    const double dx = 1e-3 * null_gap(T);
    const BridgeState plus = bridge(T, dx), minus = bridge(T, -dx);
    return ((plus.left_force - plus.right_force) - (minus.left_force - minus.right_force)) / (2 * dx);
  }
} // namespace servodrift::system
