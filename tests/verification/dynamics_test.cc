// The valve's dynamics (issue 23) on RV-1's reduced-order tables: the static operating point is the
// dynamic model at zero rates; the closed forms of model.md 2.5 (blocked armature) and of the
// control-cavity pressure; mass conservation of a cavity; a symmetric valve odd in the current; the
// linearisation against the static solver (DC gain), the nonlinear step (small step) and the
// nonlinear sine (small amplitude). The valve in operation (saturation, voltage drive, failures, the
// cold range): dynamics_operation_test.cc.
#include "common/error.h"
#include "common/thermal_laws.h"
#include "common/units.h"
#include "system/dynamic_checks.h"
#include "system/dynamics.h"
#include "system/linear_analysis.h"
#include "system/sine_response.h"
#include "system/steady_state_check.h"
#include "system/step_response.h"
#include "system/valve_model.h"
#include "tests/support/checks.h"
#include "tests/support/reduced_order_valve.h"
#include "tests/support/test_support.h"

#include <unsupported/Eigen/MatrixFunctions>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

using namespace servodrift;
using namespace servodrift::system;
using test::scaled_rates;

namespace
{
  using Valve = test::ReducedOrderValve;

  const Valve &rv1() { return test::shared_reduced_order_valve(); }

  constexpr double rated = 0.02, bias = 0.01;
} // namespace

TEST(Dynamics, StaticPointIsTheDynamicModelAtZeroRates)
{
  // One set of equations: every rate vanishes at the static operating point, to the static solver's
  // root tolerances (1e-13 of each bracket), free or saturated.
  const auto &v = rv1();
  double worst = 0;
  for (double T : {40.0, 80.0, 120.0})
    for (double i : {0.0, bias, rated, -rated})
      {
        const auto d = v.dynamics(T);
        const OperatingPoint op = v.model.solve(d.equations(), i);
        worst = test::larger(worst, scaled_rates(d, op.state(), i));
      }
  EXPECT_CHECK_AT_MOST("largest rate at the static point, 40/80/120 degC; 0, bias, +-rated [scale x sqrt(K_a/J_a)]",
                       worst, 1e-9, "every rate 0");
  // pressed onto a nozzle (E38 with theta_d = 1 deg) and the spool on its stop: the contact and the
  // stop hold the static point too
  Offsets pressed;
  pressed.spring_tube_rest_angle = -1.0 * units::degree;
  const auto d = v.dynamics(40, {}, pressed);
  const OperatingPoint op = v.model.solve(d.equations(), 0.0);
  ASSERT_EQ(op.flapper, FlapperState::on_right_nozzle);
  ASSERT_EQ(op.spool.state, SpoolState::on_negative_stop);
  EXPECT_CHECK_AT_MOST("largest rate at the static point on a nozzle and a stop, 40 degC [scale x sqrt(K_a/J_a)]",
                       scaled_rates(d, op.state(), 0.0), 1e-9, "every rate 0");
}

TEST(Dynamics, StaysAtTheStaticPointAndSettlesOnItFromRest)
{
  // issue 23: from the static point the drift stays below 1e-8 of each state's scale; from rest
  // (every pressure at return, armature and spool centred) the valve settles within 1e-6 of it
  const auto &v = rv1();
  double drift = 0, distance = 0;
  for (double T : {40.0, 120.0})
    for (double i : {bias, rated})
      {
        const auto c = steady_state_check(v.model, v.dynamics(T), i, v.description.dynamics);
        drift = test::larger(drift, c.drift_from_static);
        distance = test::larger(distance, c.distance_from_rest);
      }
  EXPECT_CHECK_AT_MOST("drift integrated from the static point, 40/120 degC, bias and rated [state scales]", drift,
                       1e-8, "stays there (issue 23)");
  EXPECT_CHECK_AT_MOST("started from rest: distance from the static point, 40/120 degC, bias and rated [state scales]",
                       distance, 1e-6, "settles on it (issue 23)");
}

TEST(Dynamics, BlockedArmatureModeIsTheClosedForm)
{
  // model.md 2.5, C13: spool blocked, control pressures following the flapper at once: the
  // armature's undamped frequency is sqrt((K_a - K_m + r^2 K_f)/J_a), about 1 kHz. The closed form
  // takes K_m as the Richardson slope of the torque table at null and K_f from the bridge by central
  // differences; the linearisation differentiates the PCHIP interpolant at the node: 0.1 % apart.
  const auto &v = rv1();
  double compressible = 0, coupled = 0;
  for (double T : {40.0, 80.0, 120.0})
    {
      const DynamicChecks c = dynamic_checks(v.model, v.dynamics(T));
      EXPECT_NEAR(c.armature_closed_form, 1005, 10) << T;
      EXPECT_CHECK_RELATIVE("armature mode, spool blocked, pressures quasi-static, " + format_number(T) + " degC [Hz]",
                            c.armature_blocked, c.armature_closed_form, 2e-3, "model.md 2.5, C13");
      // compressible cavities lag the flapper, and a free spool takes up pilot flow: each lowers it
      compressible = test::larger(compressible, c.armature_compressible / c.armature_blocked);
      coupled = test::larger(coupled, c.armature_coupled / c.armature_compressible);
    }
  EXPECT_CHECK_AT_MOST("armature mode with compressible cavities / blocked, 40-120 degC", compressible, 0.9,
                       "lower (doc/method.md)");
  EXPECT_CHECK_AT_MOST("armature mode of the coupled valve / compressible cavities, 40-120 degC", coupled, 1,
                       "lower again (doc/method.md)");
}

TEST(Dynamics, ControlCavityPressureTimeConstant)
{
  // E33 with the flapper and the spool held: dp/dt = beta_e/V (Q_0(p_s - p) - Q_N(p - p_r)), so
  // tau = V/(beta_e (dQ_0/dp + dQ_N/dp)). The linearisation equals it with the tables' slopes to the
  // difference quotients' accuracy (1e-6); for turbulent orifices (Q ~ sqrt(dp)) the closed form is
  // within the Reynolds-number dependence of C_d (E21, E22: d ln C_d/d ln dp of a few %).
  const auto &v = rv1();
  for (double T : {40.0, 120.0})
    {
      const DynamicChecks c = dynamic_checks(v.model, v.dynamics(T));
      const std::string at = ", " + format_number(T) + " degC [ms]";
      EXPECT_CHECK_RELATIVE("control-cavity time constant" + at, 1e3 * c.pressure_time_constant,
                            1e3 * c.pressure_time_constant_tables, 1e-6, "V/(beta_e dQ/dp), the tables' slopes");
      EXPECT_CHECK_RELATIVE("control-cavity time constant against turbulent orifices" + at,
                            1e3 * c.pressure_time_constant, 1e3 * c.pressure_time_constant_closed_form, 0.1,
                            "V/(beta_e (Q/(2 dp_0) + Q/(2 dp_N)))");
    }
  // in the time domain: p_L, disturbed by 0.1 % of the span, decays by e in one time constant
  const auto d = v.dynamics(40, HeldParts{true, false, true});
  const OperatingPoint null = v.model.solve(d.equations(), 0.0);
  const DynamicChecks c = dynamic_checks(v.model, v.dynamics(40));
  std::vector<double> y0 = d.vector_of(null.state());
  const double disturbance = 1e-3 * (21e6 - 0.4e6);
  y0[2] += disturbance;
  const auto integrator = d.integrator([](double) { return 0.0; }, v.description.dynamics, "test", d.vector_of(null.state()));
  integrator->start(0.0, y0);
  const double left = integrator->advance_to(c.pressure_time_constant)[2] - null.bridge.left_pressure;
  // second order in the disturbance
  EXPECT_CHECK_RELATIVE("p_L disturbance of 0.1 % after one time constant, 40 degC [of its start]",
                        left / disturbance, std::exp(-1.0), 2e-3, "e^-1");
}

TEST(Dynamics, CavityMassIsConservedOverAStep)
{
  // E33: the net flow into a control cavity is the compressibility change plus the swept volume,
  // int (Q_0 - Q_N) dt = int V/beta_e dp + A_v dx_v with V = V_0 + A_v x_v. Over the step 0 -> rated
  // the flows are integrated (Simpson on every internal step) apart from the right-hand side, and
  // the pressure term by the trapezoid rule on the same points.
  const auto &v = rv1();
  for (const bool spool_held : {true, false})
    {
      const auto d = v.dynamics(40, HeldParts{false, false, spool_held});
      const ValveEquations &eq = d.equations();
      const OperatingPoint start = v.model.solve(eq, 0.0);
      const auto integrator =
        d.integrator([](double) { return rated; }, v.description.dynamics, "test", d.vector_of(start.state()));
      integrator->start(0.0, d.vector_of(start.state()));
      const auto net_flow = [&](const std::vector<double> &y) {
        return eq.orifice_flow(left, eq.supply_pressure() - y[2]) - eq.nozzle_flow(left, eq.gaps(y[0])[0], y[2] - eq.return_pressure());
      };
      const double A_v = eq.control_area(), V_0 = eq.control_cavity_volume(), beta = eq.bulk_modulus();
      double flow = 0, compression = 0;
      std::vector<double> previous = integrator->y();
      integrator->integrate(0.02, [&](double t0, double t1) {
        const std::vector<double> &y1 = integrator->y(), middle = integrator->interpolate(0.5 * (t0 + t1));
        flow += (t1 - t0) / 6 * (net_flow(previous) + 4 * net_flow(middle) + net_flow(y1));
        const auto V = [&](const std::vector<double> &y) { return V_0 + A_v * y[4]; };
        compression += (V(previous) + 4 * V(middle) + V(y1)) / 6 / beta * (y1[2] - previous[2]);
        previous = y1;
        return true;
      });
      const double swept = A_v * (previous[4] - start.spool.displacement);
      // 3e-5 (spool held) and 3e-8 (spool free) of the flow: the quadratures' and the integrator's errors
      EXPECT_CHECK_AT_MOST(std::string("control-cavity mass balance over the step 0 -> rated, spool ") +
                             (spool_held ? "held" : "free") + ": error [of the net flow]",
                           std::abs(flow - compression - swept) / std::abs(flow), 1e-4,
                           "E33: int (Q_0 - Q_N) dt = int V/beta_e dp + A_v dx_v");
      if (spool_held)
        {
          EXPECT_EQ(swept, 0.0);
        }
    }
}

TEST(Dynamics, SymmetricValveIsOddInTheCurrent)
{
  // The pilot and the motor are symmetric: p_L - p_R is odd in the current, statically and, with
  // the spool held centred (the three-way spool itself is not symmetric, and off centre it makes the
  // two control cavities differ), along the whole transient of a step.
  const auto &v = rv1();
  double odd = 0;
  for (double T : {40.0, 120.0})
    {
      EXPECT_LT(std::abs(v.model.solve(T, rated, {}).control_pressure_difference() +
                         v.model.solve(T, -rated, {}).control_pressure_difference()),
                1e-5);
      const auto d = v.dynamics(T, HeldParts{false, false, true});
      ValveState start = v.model.solve(d.equations(), 0.0).state();
      start.spool_displacement = 0;
      const auto response = [&](double i) {
        const auto integrator = d.integrator([i](double) { return i; }, v.description.dynamics, "test", d.vector_of(start));
        integrator->start(0.0, d.vector_of(start));
        std::vector<double> dp;
        for (int k = 1; k <= 100; ++k)
          {
            const auto &y = integrator->advance_to(2e-4 * k);
            dp.push_back(y[2] - y[3]);
          }
        return dp;
      };
      const auto plus = response(rated), minus = response(-rated);
      double worst = 0, largest = 0;
      for (std::size_t k = 0; k < plus.size(); ++k)
        {
          worst = std::max(worst, std::abs(plus[k] + minus[k]));
          largest = std::max(largest, std::abs(plus[k]));
        }
      odd = test::larger(odd, worst / largest); // the integrator's step sequences differ: rtol 1e-6
    }
  EXPECT_CHECK_AT_MOST("spool held centred: (p_L - p_R)(+rated) + (p_L - p_R)(-rated) along the step, 40/120 degC "
                       "[of its largest value]",
                       odd, 1e-5, "odd in the current");
}

TEST(Dynamics, LinearisationAtZeroFrequencyIsTheStaticSensitivity)
{
  // H(0) = -C A^-1 B against the static solver's dp_B/di by central differences at the bias
  const auto &v = rv1();
  for (double T : {40.0, 120.0})
    {
      const auto d = v.dynamics(T);
      const Linearisation l = linearise(d, v.model.solve(d.equations(), bias).state(), bias);
      const double h = 1e-4 * rated;
      const double static_gain = (v.model.solve(T, bias + h, {}).spool.brake_pressure -
                                  v.model.solve(T, bias - h, {}).spool.brake_pressure) / (2 * h);
      EXPECT_CHECK_RELATIVE("DC gain of the linearisation dp_B/di at the bias, " + format_number(T) + " degC [MPa/A]",
                            1e-6 * std::real(transfer(l, Output::brake_pressure, 0.0)), 1e-6 * static_gain, 1e-4,
                            "static solver, central differences");
      EXPECT_LT(std::abs(std::imag(transfer(l, Output::brake_pressure, 0.0))), 1e-12 * static_gain);
    }
}

TEST(Dynamics, ModesAreNamedAndComplete)
{
  const auto &v = rv1();
  const auto d = v.dynamics(40);
  const Linearisation l = linearise(d, v.model.solve(d.equations(), bias).state(), bias);
  const auto m = modes(l);
  std::size_t states = 0;
  double participation = 0, decay = -std::numeric_limits<double>::infinity();
  for (const Mode &mode : m)
    {
      states += mode.eigenvalue.imag() > 0 ? 2 : 1;
      double sum = 0;
      for (double p : mode.participation)
        sum += p;
      participation = test::larger(participation, std::abs(sum - 1.0));
      decay = test::larger(decay, mode.eigenvalue.real()); // RV-1 is stable at the bias
    }
  EXPECT_CHECK_AT_MOST("modes at the bias, 40 degC: a mode's participations summed, largest error", participation,
                       1e-12, "sum 1");
  EXPECT_CHECK_AT_MOST("modes at the bias, 40 degC: largest real part of an eigenvalue [1/s]", decay, 0, "stable");
  EXPECT_EQ(states, 7u);
  std::vector<std::string> names;
  for (const Mode &mode : m)
    names.push_back(mode.name);
  bool named = true;
  for (const char *expected : {"armature-flapper", "pilot pressures", "spool + brake volume", "pilot pressures + spool"})
    {
      const bool found = std::find(names.begin(), names.end(), expected) != names.end();
      EXPECT_TRUE(found) << expected;
      named = named && found;
    }
  test::record_check("modes at the bias, 40 degC: states; names",
                     "7; armature-flapper, pilot pressures, spool + brake volume, pilot pressures + spool", "exact",
                     std::to_string(states) + (named ? "; all named" : "; a name missing"));
}

// A response is sampled up to its end: the last of its sample times is its duration, and each time
// has its state. RV-1's large steps at -15 and 10 degC are the cases where duration x (n - 1)/(n - 1)
// rounded one unit beyond the duration: the last sample was never taken and the output's last row
// read past the states.
TEST(Dynamics, StepIsSampledToItsEnd)
{
  const auto &v = rv1();
  for (const double T : {-15.0, 10.0})
    {
      const auto d = v.dynamics(T);
      const auto s = step_response(v.model, d, 0.0, rated, v.description.dynamics, 600);
      ASSERT_EQ(s.states.size(), s.times.size()) << T;
      EXPECT_EQ(s.times.back(), s.duration) << T;
      // the last state is the end of the step: within its settling band of the final value
      const double change = s.metrics[0].final - s.metrics[0].initial;
      EXPECT_CHECK_ABSOLUTE("large step at " + format_number(T) + " degC: p_B at the last sample [of the change]",
                            (s.states.back().brake_pressure - s.metrics[0].final) / change, 0.0, 0.02,
                            "the final static point (the 2 % settling band)");
    }
}

TEST(Dynamics, SmallNonlinearStepFollowsTheLinearisation)
{
  // A step of 0.01 % of rated at the bias: the nonlinear p_B(t) against the linear step response
  // C A^-1 (exp(A t) - I) B di; and the step metrics against those of the linear response.
  const auto &v = rv1();
  const auto d = v.dynamics(80);
  const OperatingPoint point = v.model.solve(d.equations(), bias);
  const Linearisation l = linearise(d, point.state(), bias);
  const double di = 1e-4 * rated;
  const auto s = step_response(v.model, d, bias, bias + di, v.description.dynamics, 400);
  // in the states' scales, where A's entries are rates of about 1e2..1e5 1/s
  const std::size_t n = l.A.rows();
  Eigen::MatrixXd A(n, n);
  Eigen::VectorXd b(n);
  for (std::size_t j = 0; j < n; ++j)
    {
      b(j) = l.B(j) * di / l.scales[j];
      for (std::size_t k = 0; k < n; ++k)
        A(j, k) = l.A(j, k) * l.scales[k] / l.scales[j];
    }
  const auto linear = [&](double t) {
    const Eigen::MatrixXd E = (A * t).exp() - Eigen::MatrixXd::Identity(n, n);
    return (A.partialPivLu().solve(E * b))(6) * l.scales[6];
  };
  const double change = s.metrics[0].final - s.metrics[0].initial;
  double worst = 0;
  for (std::size_t k = 0; k < s.times.size(); k += 7)
    {
      worst = std::max(worst, std::abs(s.states[k].brake_pressure - point.spool.brake_pressure - linear(s.times[k])));
    }
  // the valve's own nonlinearity: 1.5 % of the change for a step of 1e-3 rated, 0.15 % for 1e-4
  EXPECT_CHECK_AT_MOST("step of 1e-4 rated at the bias, 80 degC: p_B against linear, largest error [of the change]",
                       worst / std::abs(change), 5e-3, "C A^-1 (exp(A t) - I) B di");
  EXPECT_CHECK_RELATIVE("step of 1e-4 rated at the bias, 80 degC: change of p_B [Pa]", change,
                        -(A.partialPivLu().solve(b))(6) * l.scales[6], 1e-3, "-C A^-1 B di");
  // the linear response's rise time by bisection on the matrix exponential
  const auto crossing = [&](double level) {
    double a = 0, z = s.metrics[0].settling_time.value();
    for (int k = 0; k < 60; ++k)
      (linear(0.5 * (a + z)) < level * change ? a : z) = 0.5 * (a + z);
    return 0.5 * (a + z);
  };
  ASSERT_TRUE(s.metrics[0].rise_time.has_value());
  EXPECT_CHECK_RELATIVE("step of 1e-4 rated at the bias, 80 degC: rise time 10-90 % [ms]",
                        1e3 * *s.metrics[0].rise_time, 1e3 * (crossing(0.9) - crossing(0.1)), 5e-3,
                        "the linear response");
}

TEST(Dynamics, SmallSineMatchesTheLinearisationAtTheLinearLimit)
{
  // issues 23 and 61: within 0.5 dB and 3 degrees of the linearisation, below, at and above the
  // spool and brake-volume resonance (about 50 Hz at 40 degC) and at the armature's, at the default
  // bias (10 mA) and at the rated current, where the regulation loop's resonance makes the
  // response most sensitive to the amplitude. The check halves its amplitude until halving moves
  // p_B's first harmonic by at most a tenth of those limits: at the amplitude it takes, the answer
  // no longer moves when halved, so its difference to the linearisation is not the amplitude's.
  const auto &v = rv1();
  const auto &p = v.description.dynamics;
  const auto d = v.dynamics(40);
  double move_db = 0, move_degrees = 0, difference_db = 0, difference_degrees = 0;
  for (const double b : {bias, rated})
    {
      const OperatingPoint point = v.model.solve(d.equations(), b);
      const Linearisation l = linearise(d, point.state(), b);
      for (double f : {10.0, 50.0, 300.0, 730.0})
        {
          const SineCheck c = sine_check(d, l, point.state(), b, f, p.sine_check_amplitude * rated, p);
          ASSERT_GE(c.halvings.size(), 2u) << b << " A, " << f << " Hz";
          const SineResponse &taken = c.taken(), &before = c.halvings[c.halvings.size() - 2];
          const auto H = transfer(l, Output::brake_pressure, f);
          const auto move = taken.gain[0] / before.gain[0], difference = taken.gain[0] / H;
          const std::string at = std::to_string(b) + " A, " + std::to_string(f) + " Hz";
          RecordProperty("difference_db_" + std::to_string(int(1e3 * b)) + "mA_" + std::to_string(int(f)) + "Hz",
                         test::number(20 * std::log10(std::abs(difference))));
          EXPECT_TRUE(c.linear_limit) << at;
          EXPECT_TRUE(taken.periodic && before.periodic) << at;
          EXPECT_EQ(taken.response_periods, 1u) << at;
          move_db = test::larger(move_db, std::abs(20 * std::log10(std::abs(move))));
          move_degrees = test::larger(move_degrees, std::abs(std::arg(move)) / units::degree);
          difference_db = test::larger(difference_db, std::abs(20 * std::log10(std::abs(difference))));
          difference_degrees = test::larger(difference_degrees, std::abs(std::arg(difference)) / units::degree);
          EXPECT_FALSE(taken.beyond_lap) << at;
        }
    }
  const std::string points = ", 10/50/300/730 Hz, bias and rated, 40 degC";
  EXPECT_CHECK_AT_MOST("sine: the last halving moves p_B's first harmonic, largest" + points + " [dB]", move_db, 0.05,
                       "at the linear limit");
  EXPECT_CHECK_AT_MOST("sine: the last halving moves p_B's first harmonic, largest" + points + " [deg]", move_degrees,
                       0.3, "at the linear limit");
  EXPECT_CHECK_AT_MOST("sine: p_B's first harmonic against the linearisation, largest" + points + " [dB]",
                       difference_db, 0.5, "the linearisation");
  EXPECT_CHECK_AT_MOST("sine: p_B's first harmonic against the linearisation, largest" + points + " [deg]",
                       difference_degrees, 3.0, "the linearisation");
}
