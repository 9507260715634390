#include "system/valve_model.h"

#include "common/error.h"
#include "common/pilot_bridge.h"
#include "common/root_finding.h"
#include "common/thermal_laws.h"

#include <functional>
#include <stdexcept>
#include <utility>

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

  ValveState OperatingPoint::state() const
  {
    ValveState s;
    s.angle = angle;
    s.left_pressure = bridge.left_pressure;
    s.right_pressure = bridge.right_pressure;
    s.spool_displacement = spool.displacement;
    s.brake_pressure = spool.brake_pressure;
    s.coil_current = current;
    return s;
  }

  ValveModel::ValveModel(const ValveDescription &valve_, const StageTables &tables)
    : valve(valve_)
    , f(tables)
  {}

  ValveModel::ValveModel(const ValveDescription &valve_, const StageFunctions &functions)
    : valve(valve_)
    , f(functions)
  {}

  ValveEquations ValveModel::equations(double T, const Offsets &offsets) const
  {
    return ValveEquations(valve, f, T, offsets);
  }

  double ValveModel::null_gap(double T) const
  {
    return laws::pilot_stage_geometry(valve.pilot, valve.armature, valve.expansion, T,
                                      valve.operating.reference_temperature)
      .null_gap;
  }

  BridgeState ValveModel::bridge(double T, double x_f) const
  {
    return bridge(equations(T), x_f);
  }

  BridgeState ValveModel::bridge(const ValveEquations &eq, double x_f) const
  {
    const double p_s = eq.supply_pressure(), p_r = eq.return_pressure();
    BridgeState b;
    // A gap that is zero up to rounding (flapper on a nozzle) is exactly zero.
    const auto gaps = eq.gaps_at(x_f);
    b.left_gap = gaps[left];
    b.right_gap = gaps[right];
    auto half_bridge = [&](Side side, double gap, double &pressure, double &flow, double &force) {
      // E33 at rest: no spool motion, no net inflow
      pressure = bridge_pressure([&](double p) { return eq.cavity_inflow(side, gap, p, 0.0); }, p_s, p_r);
      flow = eq.nozzle_flow(side, gap, pressure - p_r);
      force = eq.flapper_force(side, gap, pressure - p_r);
    };
    half_bridge(left, b.left_gap, b.left_pressure, b.left_flow, b.left_force);
    half_bridge(right, b.right_gap, b.right_pressure, b.right_flow, b.right_force);
    return b;
  }

  SpoolSolution ValveModel::spool(double T, double dp_c) const
  {
    return spool(equations(T), dp_c);
  }

  namespace
  {
    /// Widens [lo, hi] outwards in doubling steps until the falling function g changes sign on it:
    /// g(lo) > 0 > g(hi). Used where a stiff stop holds a part just past its limit. Returns g(lo), g(hi).
    std::pair<double, double> bracket_falling(const std::function<double(double)> &g, double &lo, double &hi,
                                              double first_step, const char *what)
    {
      double g_lo = g(lo), g_hi = g(hi);
      for (double step = first_step; g_lo <= 0 && step < 1e18 * first_step; step *= 2)
        {
          hi = lo;
          g_hi = g_lo;
          lo -= step;
          g_lo = g(lo);
        }
      for (double step = first_step; g_hi >= 0 && step < 1e18 * first_step; step *= 2)
        {
          lo = hi;
          g_lo = g_hi;
          hi += step;
          g_hi = g(hi);
        }
      if (!(g_lo >= 0 && g_hi <= 0))
        throw std::runtime_error(std::string(what) + ": no balance found past the stops");
      return {g_lo, g_hi};
    }
  } // namespace

  SpoolSolution ValveModel::spool(const ValveEquations &eq, double dp_c) const
  {
    // E35 at rest, brake port blocked: the spool's net force vanishes, with the brake pressure that
    // the port's own flow balance gives at each x_v (E36, E37 at rest). The brake inflow falls with
    // p_B from >= 0 at p_r to <= 0 at p_s, and the net force falls with x_v, so both roots are unique.
    // In the lap the two land leakages divide the supply, p_B - p_r = (p_s - p_r)(x_ov + x_v)/(2 x_ov);
    // open to return (supply), the other land's leakage lifts p_B above p_r (below p_s) by a few Pa.
    const double p_s = eq.supply_pressure(), p_r = eq.return_pressure();
    const double x_ov = eq.overlap(), stroke = eq.stroke_limit();
    const auto brake_pressure = [&](double x) {
      const auto inflow = [&](double p) { return eq.brake_inflow(x, p); };
      return find_root(inflow, p_r, p_s, inflow(p_r), inflow(p_s), 1e-13 * (p_s - p_r), "brake port flow balance (E36)");
    };
    const auto net_force = [&](double x) { return eq.spool_net_force(x, 0.0, dp_c, brake_pressure(x)); };
    double lo = -stroke, hi = stroke;
    const auto [f_lo, f_hi] = bracket_falling(net_force, lo, hi, 1e-6 * stroke, "spool force balance (E35)");
    const double x = find_root(net_force, lo, hi, f_lo, f_hi, 1e-13 * stroke, "spool force balance (E35)");
    const SpoolState state = x >= stroke ? SpoolState::on_positive_stop :
                             x <= -stroke ? SpoolState::on_negative_stop :
                             x < -x_ov    ? SpoolState::vented :
                             x > x_ov     ? SpoolState::at_supply :
                                            SpoolState::regulating;
    return {x, brake_pressure(x), state};
  }

  OperatingPoint ValveModel::solve(double T, double i, const Offsets &o) const
  {
    return solve(equations(T, o), i);
  }

  OperatingPoint ValveModel::solve(const ValveEquations &eq, double i) const
  {
    const double T = eq.temperature(), x0_L = eq.null_gap(left), x0_R = eq.null_gap(right);
    // E29 at rest with E39: motor torque - spring-tube torque - flapper torque (+ nozzle contact) = 0
    const auto net_torque = [&](double theta) {
      const BridgeState b = bridge(eq, eq.flapper_displacement(theta));
      return eq.net_torque(theta, 0.0, b.left_pressure, b.right_pressure, i);
    };

    // Bracket: the nozzle contacts (x_f = -+ x0), narrowed to what the tables cover.
    double lo = eq.angle_of(-x0_R), hi = eq.angle_of(x0_L);
    bool lo_is_contact = true, hi_is_contact = true;
    auto narrow = [&](double table_lo, double table_hi) {
      if (table_lo > lo)
        lo = table_lo, lo_is_contact = false;
      if (table_hi < hi)
        hi = table_hi, hi_is_contact = false;
    };
    const auto &angles = f.torque.axis(1);
    const double angle_lo = eq.magnetic_null() + angles.front(), angle_hi = eq.magnetic_null() + angles.back();
    narrow(angle_lo, angle_hi);
    const auto &gaps = f.nozzle_conductance.axis(1);
    // left gap x0_L - x_f and right gap x0_R + x_f both within [gap_min, gap_max]
    const double x_f_lo = std::max(x0_L - gaps.back(), gaps.front() - x0_R);
    const double x_f_hi = std::min(x0_L - gaps.front(), gaps.back() - x0_R);
    narrow(eq.angle_of(x_f_lo), eq.angle_of(x_f_hi));
    if (!(lo < hi))
      throw TableRangeError("the tables leave no armature angle for the flapper at " + format_number(T) +
                            " degC (torque_motor angles and nozzle_flapper gaps do not overlap the flapper travel)");

    OperatingPoint op;
    op.temperature = T;
    op.current = i;
    const double n_lo = net_torque(lo), n_hi = net_torque(hi);
    auto table_edge = [&](const char *side) {
      // an assembly offset is the likelier cause than the grid: name it when there is one
      const Offsets &o = eq.offsets();
      const std::string offsets =
        o.magnetic_null != 0 || o.spring_tube_rest_angle != 0 ?
          "the offsets theta_m = " + format_number(o.magnetic_null) + " rad, theta_s = " +
            format_number(o.spring_tube_rest_angle) + " rad put it there (`Offsets', `Tolerances'), or extend " :
          "extend ";
      return TableRangeError(std::string("the static solution at ") + format_number(T) + " degC, i = " +
                             format_number(i) + " A lies beyond the " + side + " end of the tables' angle/gap range (" +
                             offsets + "`Sweeps/Motor angles' or `Sweeps/Gap fractions')");
    };
    const double tolerance = 1e-13 * (hi - lo) + 1e-18;
    if (n_hi >= 0 || n_lo <= 0)
      {
        // Pressed onto a nozzle: the flapper sinks into the contact until its stiffness holds the
        // net torque (a few nm for RV-1's contact); the table must reach that far.
        const bool left = n_hi >= 0;
        if (!(left ? hi_is_contact : lo_is_contact))
          throw table_edge(left ? "upper" : "lower");
        double a = left ? hi : lo, b = a;
        const auto [g_a, g_b] = bracket_falling(net_torque, a, b, 1e-9 * (hi - lo), "nozzle contact (E29)");
        if (a < angle_lo || b > angle_hi)
          throw table_edge(left ? "upper" : "lower");
        op.angle = find_root(net_torque, a, b, g_a, g_b, tolerance, "nozzle contact (E29)");
        op.flapper = left ? FlapperState::on_left_nozzle : FlapperState::on_right_nozzle;
      }
    else
      {
        op.angle = find_root(net_torque, lo, hi, n_lo, n_hi, tolerance, "torque balance (E29)");
        op.flapper = FlapperState::free;
      }
    op.flapper_displacement = eq.flapper_displacement(op.angle);
    op.bridge = bridge(eq, op.flapper_displacement);
    op.spool = spool(eq, op.control_pressure_difference());
    return op;
  }

  double ValveModel::null_flapper_displacement(const ValveEquations &eq) const
  {
    // p_L - p_R rises monotonically with x_f (the left gap closes, the right one opens). A
    // symmetric bridge is balanced at x_f = 0 exactly (both halves compute the same numbers).
    if (eq.symmetric_bridge())
      return 0.0;
    const auto imbalance = [&](double x_f) {
      const BridgeState b = bridge(eq, x_f);
      return b.left_pressure - b.right_pressure;
    };
    const auto &gaps = f.nozzle_conductance.axis(1);
    const double x0_L = eq.null_gap(left), x0_R = eq.null_gap(right);
    const double lo = std::max(x0_L - gaps.back(), gaps.front() - x0_R);
    const double hi = std::min(x0_L - gaps.front(), gaps.back() - x0_R);
    const double g_lo = imbalance(lo), g_hi = imbalance(hi);
    if (!(g_lo < 0 && g_hi > 0))
      throw TableRangeError("the pilot bridge of this asymmetric valve has no null (p_L = p_R) at " +
                            format_number(eq.temperature()) + " degC within the nozzle_flapper table's gaps (the "
                            "left and right parts differ too much; see `Asymmetry' and `Tolerances')");
    return find_root(imbalance, lo, hi, g_lo, g_hi, 1e-13 * (hi - lo), "pilot null (p_L = p_R)");
  }

  double ValveModel::nulling_hydraulic_null(const Offsets &o) const
  {
    return nulling_hydraulic_null(equations(valve.operating.reference_temperature, o));
  }

  double ValveModel::nulling_hydraulic_null(const ValveEquations &eq) const
  {
    // At the pilot null x_f* (p_L = p_R) E29 at rest holds the motor against the spring tube and
    // the jets' difference (zero for a symmetric bridge): T_em(T0, theta - theta_m, 0) =
    // K_a (theta - theta_s) + r (F_L - F_R)(x_f*); the adjustment then sets x_n = r theta - x_f*.
    const double r = valve.armature.pivot_to_nozzle_distance;
    const double x_f = null_flapper_displacement(eq);
    const BridgeState b = bridge(eq, x_f);
    const auto balance = [&](double theta) {
      return eq.with_hydraulic_null(r * theta - x_f).net_torque(theta, 0.0, b.left_pressure, b.right_pressure, 0.0);
    };
    const auto &angles = f.torque.axis(1);
    const double lo = eq.magnetic_null() + angles.front(), hi = eq.magnetic_null() + angles.back();
    const double b_lo = balance(lo), b_hi = balance(hi);
    if (!(b_lo > 0 && b_hi < 0))
      throw TableRangeError("nulling at T0: K_a (theta - theta_s) = T_em(theta - theta_m) has no root within the "
                            "torque table's angles (extend `Sweeps/Motor angles'; it also needs K_a > K_m)");
    return r * find_root(balance, lo, hi, b_lo, b_hi, 1e-13 * (hi - lo), "null adjustment at T0") - x_f;
  }

  std::optional<double> ValveModel::null_shift_current(double T, const Offsets &o) const
  {
    return null_shift_current(equations(T, o));
  }

  std::optional<double> ValveModel::null_shift_current(const ValveEquations &eq) const
  {
    const NullShift n = null_shift(eq);
    return n.beyond_table ? std::nullopt : std::optional<double>(n.current);
  }

  ValveModel::NullShift ValveModel::null_shift(const ValveEquations &eq) const
  {
    // At the pilot null (p_L = p_R, x_f*) the armature sits at theta = (x_f* + x_n)/r; the current
    // that holds it there against the spring tube and the jets' difference restores null.
    const double x_f = null_flapper_displacement(eq);
    const BridgeState b = bridge(eq, x_f);
    const double theta = eq.angle_of(x_f);
    const double a = theta - eq.magnetic_null();
    const auto &angles = f.torque.axis(1);
    const auto &currents = f.torque.axis(2);
    if (a < angles.front() || a > angles.back()) // the spring tube's torque far exceeds the motor's
      return {a > 0 ? currents.back() : currents.front(), true};
    const auto balance = [&](double i) { return eq.net_torque(theta, 0.0, b.left_pressure, b.right_pressure, i); };
    const double b_lo = balance(currents.front()), b_hi = balance(currents.back());
    if ((b_lo > 0) == (b_hi > 0) && b_lo != 0 && b_hi != 0) // the torque rises with the current
      return {b_lo > 0 ? currents.front() : currents.back(), true};
    return {find_root(balance, currents.front(), currents.back(), b_lo, b_hi, 1e-15, "null-shift current"), false};
  }

  Offsets ValveModel::described_offsets() const
  {
    const auto &base = valve.offsets;
    Offsets o{base.spring_tube_rest_angle, base.magnetic_null, base.hydraulic_null, {}, {}};
    const auto &a = valve.asymmetry;
    o.sides = {a.left, a.right};
    o.magnetic = {a.lower_gap_mismatch, a.left_remanence, a.right_remanence};
    return o;
  }

  Offsets ValveModel::offsets_for_deviation(double theta_d) const
  {
    const auto &base = valve.offsets;
    Offsets o = described_offsets();
    const double r = valve.armature.pivot_to_nozzle_distance;
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
