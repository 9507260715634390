// Least-squares polynomial fits: exact recovery of a known polynomial, statistics, refusals.
#include "common/fitting.h"

#include <gtest/gtest.h>

#include <cmath>

#include <cmath>

using namespace servodrift;

TEST(Fitting, RecoversAKnownPolynomialInTwoVariables)
{
  // y = 3 - 2 T + 0.01 T^2 + 5e5 h - 4e3 T h + 2e9 h^2 + 7e-3 T^2 h^2 ... with T ~ 100, h ~ 1e-5
  const auto exponents = full_polynomial_exponents({2, 2});
  ASSERT_EQ(exponents.size(), 9u);
  std::vector<double> c{3, 5e5, 2e9, -2, -4e3, 3e7, 0.01, 20, -1e5};
  auto eval = [&](double T, double h) {
    double y = 0;
    for (std::size_t k = 0; k < exponents.size(); ++k)
      y += c[k] * std::pow(T, exponents[k][0]) * std::pow(h, exponents[k][1]);
    return y;
  };
  std::vector<std::vector<double>> points;
  std::vector<double> values;
  for (int t = 0; t <= 8; ++t)
    for (int k = 1; k <= 7; ++k)
      {
        const double T = 40 + 10 * t, h = 10e-6 * k;
        points.push_back({T, h});
        values.push_back(eval(T, h));
      }
  const PolynomialFit fit = fit_polynomial(points, values, exponents);
  for (std::size_t k = 0; k < c.size(); ++k)
    EXPECT_LE(std::abs(fit.coefficients[k] - c[k]), 1e-10 * std::abs(c[k])) << "term " << k;
  EXPECT_NEAR(fit.r_squared, 1.0, 1e-14);
  EXPECT_LE(fit.max_abs_residual, 1e-10 * std::abs(values[0]));
  EXPECT_NEAR(fit({77, 33e-6}), eval(77, 33e-6), 1e-10 * std::abs(eval(77, 33e-6)));
  EXPECT_DOUBLE_EQ(fit.minimum[0], 40);
  EXPECT_NEAR(fit.maximum[1], 70e-6, 1e-18);
}

TEST(Fitting, PaperCubicForm)
{
  // E26's form: recovering the paper's own coefficients from its curve
  const std::vector<double> c{0.3875, 1.202e-4, -1.226e-8, 4.196e-13};
  std::vector<std::vector<double>> points;
  std::vector<double> values;
  for (double Re = 974; Re <= 11688; Re += 500)
    {
      points.push_back({Re});
      values.push_back(((c[3] * Re + c[2]) * Re + c[1]) * Re + c[0]);
    }
  const PolynomialFit fit = fit_polynomial(points, values, {{0}, {1}, {2}, {3}});
  for (int k = 0; k < 4; ++k)
    EXPECT_LE(std::abs(fit.coefficients[k] - c[k]), 1e-10 * std::abs(c[k]));
}

TEST(Fitting, StatisticsOfANoisyFit)
{
  // y_k = 2k + e_k with e_k = -1 (k even), +1 (k odd), k = 0..9. Least squares by hand:
  // slope 2 + 5/82.5, intercept 9 - slope*4.5, SS_res = 10 - 5*5/82.5, SS_tot = 360.
  std::vector<std::vector<double>> p;
  std::vector<double> y;
  for (int k = 0; k < 10; ++k)
    {
      p.push_back({double(k)});
      y.push_back(2.0 * k + (k % 2 ? 1.0 : -1.0));
    }
  const PolynomialFit fit = fit_polynomial(p, y, {{0}, {1}});
  const double slope = 2 + 5 / 82.5, ss_res = 10 - 25 / 82.5;
  EXPECT_NEAR(fit.coefficients[1], slope, 1e-13);
  EXPECT_NEAR(fit.coefficients[0], 9 - slope * 4.5, 1e-13);
  EXPECT_NEAR(fit.r_squared, 1 - ss_res / 360, 1e-13);
  EXPECT_NEAR(fit.rms_residual, std::sqrt(ss_res / 10), 1e-13);
  // the largest residuals are at k = 1 and 8: |e_k - (5/82.5)(k - 4.5)| = 1 + 3.5*5/82.5
  EXPECT_NEAR(fit.max_abs_residual, 1 + 3.5 * 5 / 82.5, 1e-13);
}

TEST(Fitting, RefusesTooFewSamples)
{
  EXPECT_THROW(fit_polynomial({{1}, {2}}, {1, 2}, {{0}, {1}, {2}}), std::invalid_argument);
  EXPECT_THROW(fit_polynomial({{1}, {1}, {1}}, {1, 2, 3}, {{0}, {1}}), std::invalid_argument); // rank deficient
}

TEST(Fitting, JsonCarriesTermsAndValidity)
{
  const PolynomialFit fit = fit_polynomial({{0}, {1}, {2}}, {1, 3, 5}, {{0}, {1}});
  const std::string json = fit.to_json().dump();
  EXPECT_NE(json.find("\"powers\": [1]"), std::string::npos) << json;
  EXPECT_NE(json.find("\"validity\""), std::string::npos);
  EXPECT_NE(json.find("\"r_squared\": 1"), std::string::npos);
}

#include "common/stage_output.h"
#include "common/table.h"
#include "tests/support/test_support.h"

TEST(TableFits, TooFewPointsLeaveOutTheFitInsteadOfFailing)
{
  // A reduced field sweep (one orifice pressure difference at two temperatures) has two Reynolds
  // numbers with flow: the cubic E26 is left out of fits.json, the general fit's degrees are capped,
  // and nothing throws (it used to end the run after the tables were written).
  Table t(schemas::fixed_orifice);
  t.rows = {{40, 0, 0, 0.778, 0, 3}, {40, 10.3e6, 3.4e-6, 0.753, 2504, 0},
            {80, 0, 0, 0.793, 0, 3}, {80, 10.3e6, 3.5e-6, 0.765, 5235, 0}};
  std::vector<PolynomialFit> fits;
  ASSERT_NO_THROW(fits = fits_of_table(t, test::valve()));
  ASSERT_EQ(fits.size(), 1u);
  EXPECT_NE(fits[0].name.find("full polynomial"), std::string::npos);
  EXPECT_NE(fits[0].note.find("capped"), std::string::npos);
}
