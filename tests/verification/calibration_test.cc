// Calibration (issue 26) on synthetic data made by the model itself from known parameters: the
// truth recovered without noise, within 2 standard errors with noise, the 95 % intervals' coverage
// over repeated noise draws, and parameters that act identically reported as not identifiable.
#include "system/calibration.h"
#include "system/calibration_model.h"
#include "system/drift_map.h"
#include "system/valve_model.h"
#include "tests/support/checks.h"
#include "tests/support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <random>

using namespace servodrift;
using namespace servodrift::system;
using test::relative;

namespace
{
  const std::vector<std::string> base = {"Dynamics/Enabled=false", "Spring tube/Model level=reduced-order",
                                         "Torque motor/Model level=reduced-order",
                                         "Pilot stage/Model level=reduced-order", "Output/Progress=none"};

  struct Bench
  {
    ValveDescription valve;
    StageTables tables;
    Bench()
      : valve(test::valve())
      , tables(StageTables::read(test::write_reduced_order_tables(valve), valve))
    {}
  };

  const Bench &bench()
  {
    static const Bench b;
    return b;
  }

  /// The points a bench would measure: the null-shift current and the brake pressure at the rated
  /// current at 50 ... 120 degC (the valve nulled at 40 degC).
  std::vector<Measurement> bench_points(bool with_brake_pressure)
  {
    std::vector<Measurement> points;
    for (double T = 50; T <= 120; T += 10)
      {
        points.push_back({0, T, 0.0, MeasuredQuantity::null_shift_current, 0.0, 2e-6});
        if (with_brake_pressure)
          points.push_back({0, T, 0.02, MeasuredQuantity::brake_pressure, 0.0, 2e4});
      }
    return points;
  }

  /// Writes the points with values `y' (SI) and their standard deviations as a measured file.
  std::string write_measured(const std::vector<Measurement> &points, const std::vector<double> &y)
  {
    const std::string path = test::temporary_directory() + "/measured.csv";
    std::ofstream out(path);
    out << "# synthetic\ntemperature[degC],current[mA],null_shift_current[mA],null_shift_current_sd[mA],"
           "brake_pressure[MPa],brake_pressure_sd[MPa]\n";
    for (std::size_t k = 0; k < points.size(); ++k)
      {
        const auto &p = points[k];
        out << p.temperature << "," << 1e3 * p.current << ",";
        if (p.quantity == MeasuredQuantity::null_shift_current)
          out << std::setprecision(17) << 1e3 * y[k] << "," << 1e3 * p.standard_deviation << ",,\n";
        else
          out << ",," << std::setprecision(17) << 1e-6 * y[k] << "," << 1e-6 * p.standard_deviation << "\n";
      }
    return path;
  }

  /// The same for the null-shift current alone, without standard deviations (sigma then estimated).
  std::string write_measured_without_sd(const std::vector<Measurement> &points, const std::vector<double> &y)
  {
    const std::string path = test::temporary_directory() + "/measured.csv";
    std::ofstream out(path);
    out << "# synthetic, no standard deviations\ntemperature[degC],current[mA],null_shift_current[mA]\n";
    for (std::size_t k = 0; k < points.size(); ++k)
      out << points[k].temperature << "," << 1e3 * points[k].current << "," << std::setprecision(17) << 1e3 * y[k] << "\n";
    return path;
  }

  CalibrationRequest request(const std::string &measured, const std::vector<std::string> &free,
                             const std::vector<std::string> &start = {})
  {
    std::vector<std::string> overrides = base;
    overrides.insert(overrides.end(), start.begin(), start.end());
    return {measured, free, "", overrides};
  }

  /// The model's values at the truth.
  std::vector<double> truth_values(const std::vector<std::string> &free, const std::vector<double> &truth,
                                   const std::vector<Measurement> &points)
  {
    CalibrationRequest r = request("", free);
    std::vector<FreeParameter> parameters;
    for (const auto &f : free)
      parameters.push_back({f, "", 0, -1, 1});
    return CalibrationModel(r, parameters, bench().tables).predict(truth, points);
  }

  const std::vector<std::string> two_free = {"Offsets/Magnetic null", "Asymmetry/Left orifice diameter deviation"};
  const std::vector<double> two_truth = {0.02, 1.5e-6}; // deg, m
  // as the checks show them: theta_m in deg, the diameter deviation in um
  const std::vector<std::string> two_names = {"theta_m [deg]", "left orifice diameter deviation [um]"};
  const std::vector<double> two_shown = {1, 1e6};
} // namespace

// Without noise the fit returns the parameters that made the data, to 1e-6 relative (the solver's
// tolerances are 1e-12 and tighter; the model's root finders round at 1e-13).
TEST(Calibration, NoiseFreeDataGiveTheTruth)
{
  const auto points = bench_points(true);
  const std::string file = write_measured(points, truth_values(two_free, two_truth, points));
  const CalibrationRequest r = request(file, two_free);
  const CalibrationSetup setup = prepare_calibration(r, bench().tables);
  const CalibrationResults c = calibrate(r, setup, bench().tables);
  for (std::size_t j = 0; j < 2; ++j)
    {
      EXPECT_CHECK_RELATIVE("noise-free data: " + two_names[j], two_shown[j] * c.estimates[j],
                            two_shown[j] * two_truth[j], 1e-6, "the truth");
      ASSERT_TRUE(c.standard_errors[j]);
    }
  EXPECT_LT(c.chi_square, 1e-10);
  EXPECT_TRUE(c.not_identifiable.empty());
  EXPECT_FALSE(c.sigma_estimated);
}

// The same without standard deviations in the file: the residuals are scaled by a first estimate of
// sigma (the data's own size), so the solver's tolerances are relative and it does not stop on its
// absolute gradient tolerance with residuals of microamperes; the truth comes back to 1e-6.
TEST(Calibration, NoiseFreeDataWithoutStandardDeviationsGiveTheTruth)
{
  const auto points = bench_points(false);
  const std::string file = write_measured_without_sd(points, truth_values(two_free, two_truth, points));
  const CalibrationRequest r = request(file, two_free);
  const CalibrationSetup setup = prepare_calibration(r, bench().tables);
  const CalibrationResults c = calibrate(r, setup, bench().tables);
  ASSERT_TRUE(c.sigma_estimated);
  for (std::size_t j = 0; j < 2; ++j)
    {
      RecordProperty("relative_error_" + std::to_string(j), test::number(relative(c.estimates[j], two_truth[j])));
      EXPECT_CHECK_RELATIVE("null-shift currents without _sd columns: " + two_names[j], two_shown[j] * c.estimates[j],
                            two_shown[j] * two_truth[j], 1e-6, "the truth");
    }
  EXPECT_EQ(c.rank, 2u);
  EXPECT_EQ(c.degrees_of_freedom, points.size() - 2);
  test::record_check("without _sd columns: rank, degrees of freedom",
                     "2, " + std::to_string(points.size() - 2) + " (free parameters, values - 2)", "exact",
                     std::to_string(c.rank) + ", " + std::to_string(c.degrees_of_freedom));
  // the residuals' scatter, far below a microampere
  EXPECT_CHECK_AT_MOST("without _sd columns: the residuals' scatter sigma [uA]", 1e6 * std::sqrt(c.reduced_chi_square),
                       1e-3, "noise-free");
}

// With Gaussian noise of the stated standard deviations the estimates lie within 2 standard errors
// of the truth (first draw), and over 100 draws the 95 % intervals cover the truth in 90-99 % of
// them for each parameter (binomial(100, 0.95): outside [90, 99] with probability 1.7 %).
SLOW_TEST(Calibration, NoisyDataCoverTheTruth)
{
  const auto points = bench_points(true);
  const std::vector<double> exact = truth_values(two_free, two_truth, points);
  std::mt19937_64 random(2026);
  std::normal_distribution<double> gauss;
  std::vector<int> covered(2, 0);
  const int draws = 100;
  for (int d = 0; d < draws; ++d)
    {
      std::vector<double> y = exact;
      for (std::size_t k = 0; k < y.size(); ++k)
        y[k] += points[k].standard_deviation * gauss(random);
      const CalibrationRequest r = request(write_measured(points, y), two_free);
      const CalibrationResults c = calibrate(r, prepare_calibration(r, bench().tables), bench().tables);
      for (std::size_t j = 0; j < 2; ++j)
        {
          ASSERT_TRUE(c.intervals[j]);
          covered[j] += c.intervals[j]->lower <= two_truth[j] && two_truth[j] <= c.intervals[j]->upper;
          if (d == 0)
            EXPECT_CHECK_AT_MOST("first noise draw: |estimate - truth| / standard error, " + two_names[j],
                                 std::abs(c.estimates[j] - two_truth[j]) / *c.standard_errors[j], 2,
                                 "2 standard errors");
        }
    }
  for (std::size_t j = 0; j < 2; ++j)
    {
      EXPECT_GE(covered[j], 90) << j;
      EXPECT_LE(covered[j], 99) << j;
      test::record_check("100 noise draws: 95 % intervals covering the truth, " + two_names[j],
                         "90 .. 99 (binomial: outside with probability 1.7 %)", "-", std::to_string(covered[j]));
    }
}

// The two magnets' remanences act on the circuit E3 only through their mean: any measurement
// sees them as one. Both are reported as not identifiable, without standard errors.
TEST(Calibration, IdenticalParametersAreNotIdentifiable)
{
  const std::vector<std::string> free = {"Asymmetry/Left magnet remanence deviation",
                                         "Asymmetry/Right magnet remanence deviation"};
  const auto points = bench_points(true);
  const std::string file = write_measured(points, truth_values(free, {0.01, 0.01}, points));
  const CalibrationRequest r = request(file, free);
  const CalibrationResults c = calibrate(r, prepare_calibration(r, bench().tables), bench().tables);
  EXPECT_EQ(c.not_identifiable.size(), 2u);
  EXPECT_FALSE(c.standard_errors[0]);
  EXPECT_FALSE(c.standard_errors[1]);
  ASSERT_FALSE(c.warnings.empty());
  EXPECT_NE(c.warnings.front().find("cannot tell apart"), std::string::npos) << c.warnings.front();
  test::record_check("both remanences free: reported not identifiable, without standard errors",
                     "both (E3 sees their mean), a warning", "-",
                     std::to_string(c.not_identifiable.size()) + " of 2"
                       + (c.standard_errors[0] || c.standard_errors[1] ? ", a standard error" : ""));
  // what the data do determine, the mean, is found and reported as the combination left + right
  EXPECT_CHECK_ABSOLUTE("both remanences free: mean of their relative deviations",
                        0.5 * (c.estimates[0] + c.estimates[1]), 0.01, 1e-6, "the truth");
  ASSERT_EQ(c.determined.size(), 1u);
  const DeterminedCombination &sum = c.determined.front();
  ASSERT_EQ(sum.coefficients.size(), 2u);
  EXPECT_CHECK_ABSOLUTE("determined combination: left's coefficient", sum.coefficients[0], sum.coefficients[1], 1e-6,
                        "right's coefficient");
  EXPECT_CHECK_ABSOLUTE("determined combination: |left's coefficient|", std::abs(sum.coefficients[0]), 1.0, 1e-12,
                        "normalised");
  EXPECT_CHECK_ABSOLUTE("determined combination left + right", sum.estimate / sum.coefficients[0], 0.02, 2e-6,
                        "the truth");
  EXPECT_GT(sum.standard_error, 0.0);
  // the sum is well determined by 16 values
  EXPECT_CHECK_AT_MOST("determined combination: its standard error", sum.standard_error, 1e-3, "16 values");
  EXPECT_NE(c.warnings.front().find("the data determine"), std::string::npos) << c.warnings.front();
  // the lost direction is not a degree of freedom: values - rank
  EXPECT_EQ(c.rank, 1u);
  EXPECT_EQ(c.degrees_of_freedom, points.size() - 1);
  test::record_check("both remanences free: rank, degrees of freedom",
                     "1, " + std::to_string(points.size() - 1) + " (values - 1)", "exact",
                     std::to_string(c.rank) + ", " + std::to_string(c.degrees_of_freedom));
}

// The D9 deviations the calibration can fit are the drift map's: a valve with theta_m = 0.01 deg,
// nulled at 40 degC, against the drift map's point at the deviation angle 0.01 deg (which drives
// theta_m), at every drift temperature.
TEST(Calibration, DeviationsAreTheDriftMapsOnes)
{
  const std::vector<std::string> map_overrides = {"Sweeps/Deviation angles=0, 0.01", "Sweeps/Drift temperatures=40, 80, 120"};
  ValveDescription v = test::valve(map_overrides);
  const ValveModel model(v, bench().tables);
  const DriftMap map = compute_drift_map(model, OutputParameters::Progress::none);
  std::vector<Measurement> points;
  for (double T : {40.0, 80.0, 120.0})
    {
      points.push_back({0, T, 0.0, MeasuredQuantity::spool_displacement_deviation, 0.0, 1.0});
      points.push_back({0, T, 0.02, MeasuredQuantity::brake_pressure_deviation, 0.0, 1.0});
    }
  const std::vector<double> y = truth_values({"Offsets/Magnetic null"}, {0.01}, points);
  double spool = 0, brake = 0; // the largest differences: m, Pa
  for (std::size_t t = 0; t < 3; ++t)
    {
      const DriftPoint &p = map.at(t, 1);
      ASSERT_NEAR(p.deviation_angle, 0.01 * M_PI / 180, 1e-18);
      spool = std::max(spool, std::abs(y[2 * t] - p.spool_displacement_deviation));
      brake = std::max(brake, std::abs(y[2 * t + 1] - p.brake_pressure_deviation));
    }
  EXPECT_CHECK_AT_MOST("D9 spool displacement deviation, 40/80/120 degC: largest difference [m]", spool, 1e-12,
                       "the drift map's");
  EXPECT_CHECK_AT_MOST("D9 brake pressure deviation at 20 mA, 40/80/120 degC: largest difference [Pa]", brake, 1e-3,
                       "the drift map's");
}
