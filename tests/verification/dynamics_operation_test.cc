// The valve's dynamics in operation (issues 23, 65) on RV-1's reduced-order tables: saturation at a
// nozzle, the voltage drive's coil, errors that name temperature and time, the cold valve's sine
// responses by shooting, a failed sine response, the cold-soak start and the large-signal study's
// temperatures. The model's own checks: dynamics_test.cc.
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

TEST(Dynamics, AFlapperDrivenOntoANozzleSaturatesAndSaysSo)
{
  // 6 times rated at 10 Hz drives the flapper onto the nozzles (x_f = x0 takes about 67 mA):
  // allowed, the contact holds it, and the response says so; the gap never goes negative beyond the
  // contact's give (force/K_c, well under a micrometre)
  const Valve wide({"Sweeps/Motor currents=-0.14, -0.1, -0.05, -0.02, 0, 0.02, 0.05, 0.1, 0.14"});
  const auto d = wide.dynamics(40);
  const OperatingPoint point = wide.model.solve(d.equations(), bias);
  const Linearisation l = linearise(d, point.state(), bias);
  const auto s = sine_response(d, l, point.state(), bias, 10, 6 * rated, wide.description.dynamics);
  EXPECT_TRUE(s.flapper_contact);
  EXPECT_CHECK_AT_LEAST("6 x rated at 10 Hz, 40 degC: largest x_f [um]", 1e6 * s.maximum[2], 40, "the nozzle, x0");
  EXPECT_CHECK_AT_MOST("6 x rated at 10 Hz, 40 degC: largest x_f [um]", 1e6 * s.maximum[2], 41, "x0 + 1 um");
  EXPECT_CHECK_AT_LEAST("6 x rated at 10 Hz, 40 degC: smallest x_f [um]", 1e6 * s.minimum[2], -41, "-(x0 + 1 um)");
  EXPECT_TRUE(std::isfinite(s.distortion));
  EXPECT_CHECK_AT_LEAST("6 x rated at 10 Hz, 40 degC: harmonic distortion of p_B", s.distortion, 0.05, "clipped");
}

TEST(Dynamics, VoltageDriveAddsTheCoil)
{
  // 1.20: L_c di/dt = u - R_c(T) i - k_e dtheta/dt. With the armature held the coil's pole is
  // -R_c(T)/L_c; at steady state i = u/R_c(T) = R_c(T0)/R_c(T) i_command.
  const Valve voltage({"Torque motor/Coil drive=voltage"});
  for (double T : {40.0, 120.0})
    {
      const auto held = voltage.dynamics(T, HeldParts{true, true, true});
      ASSERT_EQ(held.size(), 8u);
      const double R = laws::coil_resistance(voltage.description.torque_motor, T), L = 0.041;
      const OperatingPoint null = voltage.model.solve(held.equations(), 0.0);
      const Linearisation l = linearise(held, null.state(), 0.0);
      const std::string at = ", armature held, " + format_number(T) + " degC";
      EXPECT_CHECK_RELATIVE("voltage drive: coil pole" + at + " [1/s]", l.A(7, 7), -R / L, 1e-6, "-R_c(T)/L_c");
      const double R0 = laws::coil_resistance(voltage.description.torque_motor, 40);
      EXPECT_CHECK_RELATIVE("voltage drive: steady current at rated command" + at + " [mA]",
                            1e3 * held.steady_current(rated), 1e3 * rated * R0 / R, 1e-12, "R_c(T0)/R_c(T) i_command");
    }
  // the static point is the dynamic one at zero rates with the coil too
  const auto d = voltage.dynamics(80);
  const OperatingPoint op = voltage.model.solve(d.equations(), d.steady_current(bias));
  EXPECT_CHECK_AT_MOST("voltage drive: largest rate at the static point, bias, 80 degC [scale x sqrt(K_a/J_a)]",
                       scaled_rates(d, op.state(), bias), 1e-9, "every rate 0");
}

TEST(Dynamics, FailedIntegrationNamesTemperatureAndTime)
{
  // a torque table that does not reach the nozzles, and a step that drives the armature past it
  const Valve narrow({"Sweeps/Motor angles=-0.15, -0.1, -0.05, 0, 0.05, 0.1, 0.15"});
  const auto d = narrow.dynamics(60);
  try
    {
      step_response(narrow.model, d, 0.0, rated, narrow.description.dynamics, 50);
      FAIL() << "the armature passes 0.15 deg in this step";
    }
  catch (const std::runtime_error &e)
    {
      const std::string m = e.what();
      EXPECT_NE(m.find("at 60 degC"), std::string::npos) << m;
      EXPECT_NE(m.find("t = "), std::string::npos) << m;
      EXPECT_NE(m.find("Sweeps/Motor angles"), std::string::npos) << m;
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
      const bool named = m.find("at 60 degC") != std::string::npos && m.find("t = ") != std::string::npos &&
                         m.find("Sweeps/Motor angles") != std::string::npos && m.find('\n') == std::string::npos;
      test::record_check("a step past the torque table, 60 degC: the error",
                         "one line naming the temperature, the time and Sweeps/Motor angles", "-",
                         named ? "names them" : "does not");
    }
  // CVODE's own failure (too few steps allowed) likewise
  auto p = narrow.description.dynamics;
  p.maximum_steps = 100;
  try
    {
      step_response(rv1().model, rv1().dynamics(60), 0.0, rated, p, 50);
      FAIL();
    }
  catch (const std::runtime_error &e)
    {
      const std::string m = e.what();
      EXPECT_NE(m.find("at 60 degC, t = "), std::string::npos) << m;
      EXPECT_NE(m.find("CV_TOO_MUCH_WORK"), std::string::npos) << m;
      EXPECT_NE(m.find("Maximum steps"), std::string::npos) << m;
      EXPECT_NE(m.find("the steps are held down by"), std::string::npos) << m; // and the entries that set its speed
      const bool named = m.find("at 60 degC, t = ") != std::string::npos &&
                         m.find("CV_TOO_MUCH_WORK") != std::string::npos &&
                         m.find("Maximum steps") != std::string::npos &&
                         m.find("the steps are held down by") != std::string::npos;
      test::record_check("CVODE out of steps, 60 degC: the error",
                         "naming the temperature, the time, Maximum steps and what held the steps down", "-",
                         named ? "names them" : "does not");
    }
}

TEST(Dynamics, ShootingMakesTheColdValvesSineResponsePeriodicInAFewPeriods)
{
  // At -55 degC RV-1's spool and brake-volume mode decays over 5.5 s (1.7 Hz, zeta 0.017): waiting
  // for it at 1 kHz would take some 22 000 periods. Newton's method on the period map takes the
  // periodic state in a few periods whatever that mode's rate. Checked: the small-signal sine is
  // periodic within `Maximum periods', and within the check's limits (0.5 dB, 3 deg) of the
  // linearisation; a large signal (a quarter of rated, the spool beyond its lap) ends without an
  // error, periodic or not, and says which.
  const auto &v = rv1();
  const auto &p = v.description.dynamics;
  const auto d = v.dynamics(-55);
  const OperatingPoint point = v.model.solve(d.equations(), bias);
  const Linearisation l = linearise(d, point.state(), bias);
  ASSERT_LT(slowest_decay_rate(l), 0.5); // the slow mode this test is about
  const SineCheck c = sine_check(d, l, point.state(), bias, 1000, p.sine_check_amplitude * rated, p);
  const SineResponse &taken = c.taken();
  ASSERT_TRUE(taken.periodic);
  EXPECT_CHECK_AT_MOST("small-signal sine, -55 degC, 1 kHz, bias: periods to the periodic state", taken.periods,
                       p.maximum_periods, "Maximum periods");
  const auto difference = taken.gain[0] / transfer(l, Output::brake_pressure, 1000);
  RecordProperty("cold_sine_difference_db", test::number(20 * std::log10(std::abs(difference))));
  EXPECT_CHECK_AT_MOST("small-signal sine, -55 degC, 1 kHz, bias: p_B's first harmonic against the linearisation [dB]",
                       std::abs(20 * std::log10(std::abs(difference))), 0.5, "the linearisation");
  EXPECT_CHECK_AT_MOST("small-signal sine, -55 degC, 1 kHz, bias: p_B's first harmonic against the linearisation [deg]",
                       std::abs(std::arg(difference)) / units::degree, 3.0, "the linearisation");
  const SineResponse large = sine_response(d, l, point.state(), bias, 1000, 0.25 * rated, p);
  EXPECT_TRUE(large.failure.empty()) << large.failure;
  EXPECT_GT(large.periods, 0u);
}

TEST(Dynamics, ASineResponseWhoseIntegrationFailsSaysWhyAndDoesNotStopTheRun)
{
  // CVODE's steps run out: the response is not periodic and carries the message (temperature,
  // time, the entry to change); the dynamics stage writes it as integration_failed
  const auto &v = rv1();
  auto p = v.description.dynamics;
  p.maximum_steps = 50;
  const auto d = v.dynamics(60);
  const OperatingPoint point = v.model.solve(d.equations(), bias);
  const Linearisation l = linearise(d, point.state(), bias);
  const SineResponse s = sine_response(d, l, point.state(), bias, 20, 0.25 * rated, p);
  EXPECT_FALSE(s.periodic);
  EXPECT_NE(s.failure.find("at 60 degC, 20 Hz, t = "), std::string::npos) << s.failure;
  EXPECT_NE(s.failure.find("Maximum steps"), std::string::npos) << s.failure;
  const bool kept = !s.periodic && s.failure.find("at 60 degC, 20 Hz, t = ") != std::string::npos &&
                    s.failure.find("Maximum steps") != std::string::npos;
  test::record_check("a sine whose integration fails, 60 degC, 20 Hz",
                     "not periodic; the reason names the temperature, the frequency, the time and Maximum steps", "-",
                     kept ? "so" : "not so");
}

TEST(Dynamics, ColdSoakStartRegulatesOnTheStaticPointAndSlowerWhenCold)
{
  // From rest (every pressure at return) with supply and the rated current applied, the valve ends
  // on its static operating point at the rated current (the response runs 8 time constants of its
  // slowest mode: within e^-8 of the start's distance, about 1 in the states' scales, so 1e-3), and
  // its brake pressure settles within 2 % of the change; the cold oil slows the pressure loop (its
  // slowest mode decays 70 times slower at -55 than at 40 degC), so the cold valve takes longer
  // to regulate.
  const auto &v = rv1();
  std::map<double, double> regulated;
  for (double T : {-55.0, 40.0})
    {
      const auto d = v.dynamics(T);
      const StepResponse s = start_up_response(v.model, d, rated, v.description.dynamics, 50);
      const OperatingPoint end = v.model.solve(d.equations(), rated);
      const std::string at = "cold-soak start at the rated current, " + format_number(T) + " degC: ";
      EXPECT_CHECK_AT_MOST(at + "distance of the end from the static point [state scales]", s.final_distance, 1e-3,
                           "e^-8 of the start after 8 time constants");
      EXPECT_CHECK_RELATIVE(at + "final p_B [MPa]", 1e-6 * s.metrics[0].final, 1e-6 * end.spool.brake_pressure, 1e-12,
                            "the static point");
      EXPECT_DOUBLE_EQ(s.metrics[0].initial, d.equations().return_pressure()) << T;
      ASSERT_TRUE(s.metrics[0].settling_time.has_value()) << T;
      regulated[T] = *s.metrics[0].settling_time;
      RecordProperty("cold_start_time_to_regulate_s_at_" + std::to_string(int(T)), test::number(regulated[T]));
    }
  EXPECT_CHECK_AT_LEAST("cold-soak start at the rated current, -55 degC: time to regulate p_B within 2 % [s]",
                        regulated[-55], 3 * regulated[40], "slower when cold: 3 x the time at 40 degC");
}

TEST(Dynamics, LargeSignalStudyTemperaturesAreTheEndsAndEvenlySpread)
{
  using V = std::vector<std::size_t>;
  EXPECT_EQ(system::study_indices(17, 5), (V{0, 4, 8, 12, 16}));
  EXPECT_EQ(system::study_indices(9, 5), (V{0, 2, 4, 6, 8}));
  EXPECT_EQ(system::study_indices(10, 4), (V{0, 3, 6, 9}));
  EXPECT_EQ(system::study_indices(4, 1), (V{0}));
  EXPECT_EQ(system::study_indices(3, 5), (V{0, 1, 2}));
  EXPECT_EQ(system::study_indices(2, 2), (V{0, 1}));
}
