// Monotone cubic interpolation on tensor grids: exact at nodes and for linear data, no overshoot,
// bounds checks that name table, variable, value and range.
#include "common/error.h"
#include "common/grid_function.h"
#include "common/table.h"

#include <gtest/gtest.h>

#include <cmath>

#include <cmath>

using namespace servodrift;

namespace
{
  GridFunction grid3(const std::function<double(double, double, double)> &f)
  {
    const std::vector<double> x{0, 1, 2.5, 3}, y{-1, 0, 0.5, 2, 4}, z{10, 20, 40};
    std::vector<double> v;
    for (double a : x)
      for (double b : y)
        for (double c : z)
          v.push_back(f(a, b, c));
    return GridFunction("test table", {"x[m]", "y[1]", "z[Pa]"}, {x, y, z}, v);
  }
} // namespace

TEST(GridFunction, ExactAtNodesAndForLinearData)
{
  const auto f = [](double a, double b, double c) { return 2 * a - 3 * b + 0.5 * c + 1; };
  const GridFunction g = grid3(f);
  EXPECT_DOUBLE_EQ(g(2.5, 0.5, 20), f(2.5, 0.5, 20));
  for (double a : {0.0, 0.3, 1.7, 2.9, 3.0})
    for (double b : {-1.0, -0.2, 1.1, 3.9})
      for (double c : {10.0, 17.0, 33.0, 40.0})
        EXPECT_NEAR(g(a, b, c), f(a, b, c), 1e-12) << a << " " << b << " " << c;
}

TEST(GridFunction, MonotoneDataGiveNoOvershoot)
{
  // a step: cubic splines overshoot here, PCHIP must not
  const GridFunction g("step", {"x[1]"}, {{0, 1, 2, 3, 4}}, {0, 0, 0, 1, 1});
  for (double x = 0; x <= 4; x += 0.01)
    {
      EXPECT_GE(g(x), -1e-15);
      EXPECT_LE(g(x), 1 + 1e-15);
    }
  // and it is monotone
  double last = -1;
  for (double x = 0; x <= 4; x += 0.01)
    {
      EXPECT_GE(g(x), last - 1e-15);
      last = g(x);
    }
}

TEST(GridFunction, ThirdOrderOnSmoothData)
{
  // error of a smooth monotone function falls at least with h^3 when the grid is refined
  auto error = [](int n) {
    std::vector<double> x, v;
    for (int k = 0; k <= n; ++k)
      {
        x.push_back(double(k) / n);
        v.push_back(std::exp(x.back()));
      }
    const GridFunction g("exp", {"x[1]"}, {x}, v);
    double e = 0;
    for (double t = 0.2; t <= 0.8; t += 0.001)
      e = std::max(e, std::abs(g(t) - std::exp(t)));
    return e;
  };
  const double rate = std::log2(error(16) / error(32));
  EXPECT_GT(rate, 2.8) << "observed order " << rate;
}

TEST(GridFunction, OddDataGiveOddValues)
{
  // the symmetric-valve tests rely on this: torque tables odd in the angle interpolate oddly
  std::vector<double> x{-0.3, -0.2, -0.1, 0, 0.1, 0.2, 0.3}, v;
  for (double a : x)
    v.push_back(std::sin(a) + a * a * a);
  const GridFunction g("odd", {"angle[rad]"}, {x}, v);
  for (double a = 0; a <= 0.3; a += 0.0137)
    EXPECT_NEAR(g(a), -g(-a), 1e-16);
}

TEST(GridFunction, QueryOutsideNamesTableVariableValueAndRange)
{
  const GridFunction g = grid3([](double a, double, double) { return a; });
  try
    {
      g(1, 5, 20);
      FAIL();
    }
  catch (const TableRangeError &e)
    {
      EXPECT_STREQ(e.what(), "test table: y[1] = 5 is outside the table's range [-1, 4]");
    }
  EXPECT_NO_THROW(g(3 + 1e-12, 4, 40)); // rounding at the edge is tolerated
}

TEST(GridFunction, FromTableChecksTheGrid)
{
  Table t(schemas::fixed_orifice);
  for (double T : {40.0, 80.0})
    for (double dp : {0.0, 1e6, 2e6})
      t.rows.push_back({T, dp, dp * 1e-12, 0.7, 100, 0});
  const GridFunction q = GridFunction::from_table(t, "fixed_orifice", "flow_rate");
  EXPECT_NEAR(q(60, 1.5e6), 1.5e-6, 1e-18);
  t.rows.pop_back();
  EXPECT_THROW(GridFunction::from_table(t, "fixed_orifice", "flow_rate"), InputError);
  t.rows.push_back(t.rows.front());
  EXPECT_THROW(GridFunction::from_table(t, "fixed_orifice", "flow_rate"), InputError);
}
