// The tolerance study (issue 25): the Sobol' estimators on functions with known indices through the
// study's own path, the Monte Carlo against linearised propagation, the yield's interval and the
// seeded draws. The asymmetric valve it samples: asymmetric_valve_test.cc.
#include "system/tolerance_study.h"
#include "system/valve_model.h"
#include "tests/support/checks.h"
#include "tests/support/reduced_order_valve.h"
#include "tests/support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace servodrift;
using namespace servodrift::system;
using test::larger;
using test::relative;

namespace
{
  using Valve = test::ReducedOrderValve;

  const std::vector<std::string> few_temperatures = {"Sweeps/Drift temperatures=40, 80, 120"};

  const Valve &rv1() { return test::shared_reduced_order_valve(few_temperatures); }

  ToleranceParameters uniform_inputs(std::size_t n, double half_width, unsigned int base_samples)
  {
    ToleranceParameters t{};
    t.samples = 1000;
    t.seed = 7;
    t.sobol_base_samples = base_samples;
    t.sobol_estimator = ToleranceParameters::SobolEstimator::martinez;
    t.bootstrap_size = 200;
    t.confidence_level = 0.95;
    t.sampling = ToleranceParameters::Sampling::monte_carlo;
    for (const auto &[name, unit] : ToleranceParameters::quantities())
      t.distributions.push_back({name, unit});
    for (std::size_t k = 0; k < n; ++k)
      {
        t.distributions[k].kind = ToleranceDistribution::Kind::uniform;
        t.distributions[k].lower = -half_width;
        t.distributions[k].upper = half_width;
      }
    return t;
  }

  double ishigami(const std::vector<double> &x)
  {
    return std::sin(x[0]) + 7 * std::pow(std::sin(x[1]), 2) + 0.1 * std::pow(x[2], 4) * std::sin(x[0]);
  }
} // namespace

// The estimators through the study's own path (design, sweep runner, OpenTURNS), the valve
// replaced by the Ishigami function (a = 7, b = 0.1, x_i ~ U(-pi, pi)): first-order 0.314, 0.442,
// 0 and total 0.558, 0.442, 0.244. At N = 16384 every estimate lies within 0.03 of the truth. The
// 95 % bootstrap intervals: of the 18 (3 estimators x 6 indices), each misses the truth with
// probability 0.05, so at most 3 may miss (binomial: more than 3 misses has probability 1.1 %).
TEST(SobolIndices, IshigamiThroughTheStudyPath)
{
  const std::vector<double> first = {0.3139, 0.4424, 0.0}, total = {0.5576, 0.4424, 0.2437};
  int misses = 0;
  using Estimator = ToleranceParameters::SobolEstimator;
  for (const auto &[estimator, name] :
       {std::pair{Estimator::saltelli, "Saltelli"}, std::pair{Estimator::jansen, "Jansen"},
        std::pair{Estimator::martinez, "Martinez"}})
    {
      ToleranceParameters t = uniform_inputs(3, M_PI, 16384);
      t.sobol_estimator = estimator;
      const SobolStudy s = sobol_study(t, {"ishigami"}, [](const auto &x) { return std::vector<double>{ishigami(x)}; },
                                       OutputParameters::Progress::none);
      ASSERT_EQ(s.evaluations, 16384u * 5);
      const SobolIndices &ix = s.indices.front();
      double error = 0;
      for (std::size_t k = 0; k < 3; ++k)
        {
          error = larger(error, std::abs(ix.first_order[k] - first[k]));
          error = larger(error, std::abs(ix.total[k] - total[k]));
          misses += !(ix.first_order_interval[k].lower <= first[k] && first[k] <= ix.first_order_interval[k].upper);
          misses += !(ix.total_interval[k].lower <= total[k] && total[k] <= ix.total_interval[k].upper);
        }
      EXPECT_CHECK_AT_MOST(std::string("Ishigami, N = 16 384, ") + name + ": largest |S_i - exact|, |ST_i - exact|",
                           error, 0.03, "S = 0.314, 0.442, 0; ST = 0.558, 0.442, 0.244");
    }
  EXPECT_CHECK_AT_MOST("Ishigami: 95 % intervals missing the exact index, of 18", misses, 3,
                       "binomial: more than 3 has probability 1.1 %");
}

// A linear response y = sum a_i x_i of independent inputs: S_i = ST_i = a_i^2 s_i^2 / sum, within
// 0.03 at N = 8192 (the Ishigami criterion).
TEST(SobolIndices, LinearResponseHasTheKnownDecomposition)
{
  ToleranceParameters t = uniform_inputs(4, 1.0, 8192);
  const std::vector<double> a = {1.0, 2.0, 0.5, 0.0};
  const SobolStudy s = sobol_study(
    t, {"linear"},
    [&](const auto &x) {
      double y = 0;
      for (std::size_t k = 0; k < 4; ++k)
        y += a[k] * x[k];
      return std::vector<double>{y};
    },
    OutputParameters::Progress::none);
  const double sum = 1 + 4 + 0.25; // the uniform inputs' variance 1/3 cancels
  double error = 0;
  for (std::size_t k = 0; k < 4; ++k)
    {
      const double exact = a[k] * a[k] / sum;
      error = larger(error, std::abs(s.indices[0].first_order[k] - exact));
      error = larger(error, std::abs(s.indices[0].total[k] - exact));
    }
  EXPECT_CHECK_AT_MOST("linear response of 4 uniform inputs, N = 8 192: largest |S_i - exact|, |ST_i - exact|", error,
                       0.03, "a_i^2 / sum a^2");
  // an output that nothing moves has no variance to share: flagged, not an error
  const SobolStudy flat = sobol_study(t, {"constant"}, [](const auto &) { return std::vector<double>{1.5}; },
                                      OutputParameters::Progress::none);
  EXPECT_FALSE(flat.indices[0].defined());
  EXPECT_EQ(flat.indices[0].total, std::vector<double>(4, 0.0));
}

// An output that varies only by round-off is not indexed either: below the floor its indices are
// undefined with the reason; the same output scaled above the floor is indexed.
TEST(SobolIndices, OutputBelowItsFloorIsNotIndexed)
{
  ToleranceParameters t = uniform_inputs(2, 1.0, 256);
  const auto noise = [](double scale) {
    return [scale](const std::vector<double> &x) { return std::vector<double>{scale * (x[0] + 0.1 * x[1])}; };
  };
  const SobolStudy tiny = sobol_study(t, {"tiny"}, noise(1e-12), OutputParameters::Progress::none, 1e-6);
  EXPECT_FALSE(tiny.indices[0].defined());
  EXPECT_NE(tiny.indices[0].undefined.find("floor"), std::string::npos) << tiny.indices[0].undefined;
  const bool names_floor = tiny.indices[0].undefined.find("floor") != std::string::npos;
  const std::string tiny_indices = tiny.indices[0].defined() ? "defined"
                                   : names_floor               ? "undefined, floor named"
                                                               : "undefined";
  test::record_check("Sobol' indices of an output of scale 1e-12 against a floor of 1e-6",
                     "undefined, naming the floor", "exact", tiny_indices);
  const SobolStudy real = sobol_study(t, {"real"}, noise(1.0), OutputParameters::Progress::none, 1e-6);
  ASSERT_TRUE(real.indices[0].defined());
  EXPECT_CHECK_AT_LEAST("the same output of scale 1: ST_1", real.indices[0].total[0], 0.9, "indexed");
}

// In the valve's own study the null shift at the nulling temperature is zero for every valve (to
// round-off): no indices; the maximum over the range and the hot end have them.
TEST(ToleranceStudy, NullShiftAtTheNullingTemperatureHasNoIndices)
{
  Valve v({"Sweeps/Drift temperatures=40, 80, 120", "Tolerances/Samples=20", "Tolerances/Sobol base samples=32",
           "Tolerances/Left orifice diameter/Distribution=normal", "Tolerances/Left orifice diameter/Standard deviation=1e-6",
           "Tolerances/Magnetic null/Distribution=normal", "Tolerances/Magnetic null/Standard deviation=1e-4"});
  const ToleranceResults r = compute_tolerances(v.model, OutputParameters::Progress::none);
  ASSERT_TRUE(r.sobol);
  ASSERT_EQ(r.sobol->outputs.size(), 3u);
  EXPECT_TRUE(r.sobol->indices[0].defined());
  EXPECT_FALSE(r.sobol->indices[1].defined()) << r.sobol->outputs[1];
  EXPECT_TRUE(r.sobol->indices[2].defined());
  test::record_check("valve study: Sobol' indices of the null shift at the nulling temperature",
                     "undefined (zero to round-off)", "exact", r.sobol->indices[1].defined() ? "defined" : "undefined");
  RecordProperty("nulling_temperature_output_variance", test::number(r.sobol->output_variance[1]));
}

// The Monte Carlo of the valve itself against first-order propagation of its own model: for small
// tolerances the null shift at 120 degC is linear in the deviations, y ~ sum g_i x_i with g_i from
// central differences, so its mean is ~0 and its standard deviation sqrt(sum g_i^2 s_i^2). With
// n = 1000 normal draws the sample standard deviation has a relative standard error of
// 1/sqrt(2(n - 1)) = 2.2 %, the mean one of s/sqrt(n): both checked at 3 standard errors.
TEST(ToleranceStudy, MonteCarloMatchesLinearisedPropagation)
{
  const ValveModel &m = rv1().model;
  ToleranceParameters t = uniform_inputs(0, 0, 0);
  const std::vector<std::pair<std::size_t, double>> inputs = {{0, 1e-6}, {3, 1e-6}, {4, 0.5e-6}, {11, 1e-4}, {12, 1e-6}};
  std::vector<std::size_t> quantities;
  for (const auto &[q, sd] : inputs)
    {
      t.distributions[q].kind = ToleranceDistribution::Kind::normal;
      t.distributions[q].standard_deviation = sd;
      quantities.push_back(q);
    }
  const ThermalNullShiftEvaluator e(m, {40, 120}, false);
  const auto hot_shift = [&](const std::vector<double> &x) {
    return e.evaluate(built_valve(m, quantities, x)).null_shift_current.back();
  };
  double variance = 0;
  for (std::size_t k = 0; k < inputs.size(); ++k)
    {
      std::vector<double> plus(inputs.size(), 0.0), minus(inputs.size(), 0.0);
      const double h = 0.1 * inputs[k].second;
      plus[k] = h;
      minus[k] = -h;
      const double g = (hot_shift(plus) - hot_shift(minus)) / (2 * h);
      variance += g * g * inputs[k].second * inputs[k].second;
    }
  const double predicted = std::sqrt(variance);
  const SampleRows valves = draw_valves(t);
  ASSERT_EQ(valves.size(), 1000u);
  double mean = 0, square = 0;
  for (const auto &x : valves)
    {
      const double y = hot_shift(x);
      mean += y / 1000;
      square += y * y / 1000;
    }
  const double sd = std::sqrt((square - mean * mean) * 1000 / 999);
  EXPECT_CHECK_AT_LEAST("linearised standard deviation of the null shift at 120 degC [uA]", 1e6 * predicted, 1.0,
                        "a shift worth measuring");
  EXPECT_CHECK_AT_MOST("Monte Carlo, 1 000 valves: |mean null shift| at 120 degC [uA]", 1e6 * std::abs(mean),
                       1e6 * 3 * predicted / std::sqrt(1000.0), "0, within 3 standard errors s/sqrt(n)");
  EXPECT_CHECK_RELATIVE("Monte Carlo, 1 000 valves: standard deviation of the null shift at 120 degC [uA]", 1e6 * sd,
                        1e6 * predicted, 3 / std::sqrt(2 * 999.0), "linearised, 3 standard errors");
}

// The yield's interval is the exact binomial one: at the ends it has the closed forms
// (alpha/2)^(1/n) (all pass: lower bound) and 1 - (alpha/2)^(1/n) (none pass: upper bound).
TEST(ToleranceStudy, YieldIntervalIsClopperPearson)
{
  double error = 0;
  for (std::size_t n : {10u, 1000u})
    {
      const Interval all = proportion_interval(n, n, 0.95), none = proportion_interval(0, n, 0.95);
      error = larger(error, relative(all.lower, std::pow(0.025, 1.0 / double(n))));
      EXPECT_EQ(all.upper, 1.0);
      EXPECT_EQ(none.lower, 0.0);
      error = larger(error, relative(none.upper, 1 - std::pow(0.025, 1.0 / double(n))));
    }
  EXPECT_CHECK_AT_MOST("yield interval at n and 0 passes of n = 10, 1 000: bounds, relative", error, 1e-10,
                       "(alpha/2)^(1/n), 1 - (alpha/2)^(1/n)");
  const Interval half = proportion_interval(50, 100, 0.95);
  EXPECT_CHECK_ABSOLUTE("yield interval at 50 of 100 passes: lower bound", half.lower, 0.3983, 1e-4, "Clopper-Pearson");
  EXPECT_CHECK_ABSOLUTE("yield interval at 50 of 100 passes: upper bound", half.upper, 0.6017, 1e-4, "Clopper-Pearson");
}

// Same seed, same valves; another seed, others. Latin hypercube and the randomised Sobol' sequence
// draw from the same marginals (means within 3 standard errors of 0).
TEST(ToleranceStudy, SeededDraws)
{
  ToleranceParameters t = uniform_inputs(2, 1e-6, 0);
  const bool same = draw_valves(t) == draw_valves(t);
  EXPECT_TRUE(same);
  ToleranceParameters other = t;
  other.seed = 8;
  const bool others = draw_valves(t) != draw_valves(other);
  EXPECT_TRUE(others);
  test::record_check("Monte Carlo draws: the same seed; another seed", "the same valves; others", "exact",
                     std::string(same ? "the same" : "others") + "; " + (others ? "others" : "the same"));
  using Sampling = ToleranceParameters::Sampling;
  for (const auto &[sampling, name] : {std::pair{Sampling::latin_hypercube, "Latin hypercube"},
                                       std::pair{Sampling::randomised_sobol_sequence, "randomised Sobol' sequence"}})
    {
      t.sampling = sampling;
      const SampleRows rows = draw_valves(t);
      ASSERT_EQ(rows.size(), 1000u);
      double mean = 0;
      for (const auto &x : rows)
        mean += x[0] / 1000;
      EXPECT_CHECK_AT_MOST(std::string(name) + ", 1 000 draws of U(-1, 1) um: |mean| [um]", 1e6 * std::abs(mean),
                           1e6 * 3 * (1e-6 / std::sqrt(3.0)) / std::sqrt(1000.0), "0, within 3 standard errors");
    }
}

// A tolerance wide enough to put some valves outside the tables (a magnetic null of 1 mrad standard
// deviation moves the rated operating point beyond the angle range for about 15 % of them) is not a
// crash of the study: those valves are flagged, fail the spec, have no statistics, and the report's
// example names the tolerance and its value; the Sobol' design, incomplete, has no indices.
TEST(ToleranceStudy, ValvesOutsideTheTablesAreCountedAsFailing)
{
  Valve v({"Sweeps/Drift temperatures=40, 80, 120", "Tolerances/Samples=100", "Tolerances/Sobol base samples=64",
           "Tolerances/Magnetic null/Distribution=normal", "Tolerances/Magnetic null/Standard deviation=1e-3"});
  const ToleranceResults r = compute_tolerances(v.model, OutputParameters::Progress::none);
  ASSERT_GT(r.outside_tables, 0u);
  ASSERT_LT(r.outside_tables, r.valves.size());
  std::size_t flagged = 0;
  for (std::size_t k = 0; k < r.valves.size(); ++k)
    if (r.valves[k].flags & ThermalNullShift::outside_tables)
      {
        ++flagged;
        EXPECT_FALSE(r.pass[k]) << k;
      }
  EXPECT_EQ(flagged, r.outside_tables);
  EXPECT_LE(r.passes, r.valves.size() - r.outside_tables);
  EXPECT_NE(r.outside_example.find("`Tolerances/Magnetic null' = "), std::string::npos) << r.outside_example;
  ASSERT_TRUE(r.sobol);
  EXPECT_FALSE(r.sobol->indices[0].defined());
  EXPECT_NE(r.sobol->indices[0].undefined.find("outside the tables"), std::string::npos) << r.sobol->indices[0].undefined;
  RecordProperty("valves_outside_the_tables", std::to_string(r.outside_tables));
}
