#include "common/grid_function.h"

#include "common/error.h"
#include "common/table.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace servodrift
{
  namespace
  {
    /// PCHIP slope at interior node k from the neighbouring secants (Fritsch-Carlson, weighted
    /// harmonic mean; zero at a local extremum, which keeps the interpolant monotone).
    double interior_slope(double h0, double h1, double d0, double d1)
    {
      if (d0 * d1 <= 0)
        return 0;
      const double w1 = 2 * h1 + h0, w2 = h1 + 2 * h0;
      return (w1 + w2) / (w1 / d0 + w2 / d1);
    }

    /// One-sided three-point slope at an end node, limited to keep the shape (as in SciPy's pchip).
    double end_slope(double h0, double h1, double d0, double d1)
    {
      double m = ((2 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
      if (m * d0 <= 0)
        m = 0;
      else if (d0 * d1 <= 0 && std::abs(m) > 3 * std::abs(d0))
        m = 3 * d0;
      return m;
    }

    /// The PCHIP slope at node k of the m >= 3 nodes (x, y): an end slope where node k is an end of
    /// the grid (node 0 if `starts_grid', node m - 1 if `ends_grid'), else the interior slope
    /// (0 at a stencil's end that is not the grid's: never asked for, the query's segment is inside).
    double node_slope(const double *x, const double *y, std::size_t m, std::size_t k, bool starts_grid, bool ends_grid)
    {
      const auto secant = [&](std::size_t j) { return (y[j + 1] - y[j]) / (x[j + 1] - x[j]); };
      const auto width = [&](std::size_t j) { return x[j + 1] - x[j]; };
      if (k == 0)
        return starts_grid ? end_slope(width(0), width(1), secant(0), secant(1)) : 0.0;
      if (k == m - 1)
        return ends_grid ? end_slope(width(k - 1), width(k - 2), secant(k - 1), secant(k - 2)) : 0.0;
      return interior_slope(width(k - 1), width(k), secant(k - 1), secant(k));
    }

    /// The cubic Hermite interpolant on [x0, x0 + h] at t = (x - x0)/h from the ends' values and slopes.
    double hermite(double t, double h, double y0, double y1, double m0, double m1)
    {
      const double t2 = t * t, t3 = t2 * t;
      return (2 * t3 - 3 * t2 + 1) * y0 + (t3 - 2 * t2 + t) * h * m0 + (-2 * t3 + 3 * t2) * y1 + (t3 - t2) * h * m1;
    }
  } // namespace

  GridFunction::GridFunction(std::string table_label, std::vector<std::string> axis_names_,
                             std::vector<std::vector<double>> axes_, std::vector<double> values_)
    : label(std::move(table_label))
    , axis_names(std::move(axis_names_))
    , axes(std::move(axes_))
    , values(std::move(values_))
  {
    if (axes.empty() || axes.size() > 3 || axis_names.size() != axes.size())
      throw std::logic_error("GridFunction: 1 to 3 named axes");
    std::size_t n = 1;
    strides.assign(axes.size(), 1);
    for (std::size_t k = axes.size(); k-- > 0;)
      {
        if (axes[k].size() < 2)
          throw InputError(label + ": axis `" + axis_names[k] + "' needs at least two values for interpolation");
        strides[k] = n;
        n *= axes[k].size();
      }
    if (values.size() != n)
      throw std::logic_error("GridFunction: value count does not match the grid");
    // The slopes along the last axis depend on the table alone: set once instead of at each query.
    const std::vector<double> &g = axes.back();
    last_axis_slopes.assign(n, 0.0);
    if (g.size() >= 3)
      for (std::size_t line = 0; line < n; line += g.size())
        for (std::size_t k = 0; k < g.size(); ++k)
          last_axis_slopes[line + k] = node_slope(g.data(), values.data() + line, g.size(), k, true, true);
  }

  GridFunction GridFunction::from_table(const Table &table, const std::string &table_label,
                                        const std::function<double(const std::vector<double> &)> &value_of_row)
  {
    const unsigned int d = table.schema().n_axes;
    std::vector<std::vector<double>> axes(d);
    std::vector<std::string> names(d);
    for (unsigned int k = 0; k < d; ++k)
      {
        names[k] = table.schema().columns[k].header();
        for (const auto &r : table.rows)
          axes[k].push_back(r[k]);
        std::sort(axes[k].begin(), axes[k].end());
        axes[k].erase(std::unique(axes[k].begin(), axes[k].end()), axes[k].end());
      }
    std::size_t n = 1;
    for (const auto &a : axes)
      n *= a.size();
    if (table.rows.size() != n)
      throw InputError(table_label + ": " + std::to_string(table.rows.size()) + " rows do not form a full grid of " +
                       std::to_string(n) + " points over its axes");
    std::vector<double> values(n);
    std::vector<bool> seen(n, false);
    for (const auto &r : table.rows)
      {
        std::size_t index = 0;
        for (unsigned int k = 0; k < d; ++k)
          index = index * axes[k].size() +
                  static_cast<std::size_t>(std::lower_bound(axes[k].begin(), axes[k].end(), r[k]) - axes[k].begin());
        if (seen[index])
          throw InputError(table_label + ": a grid point appears twice (the rows do not form a full grid)");
        seen[index] = true;
        values[index] = value_of_row(r);
      }
    return GridFunction(table_label, names, axes, values);
  }

  GridFunction GridFunction::from_table(const Table &table, const std::string &table_label, const std::string &column)
  {
    const std::size_t c = table.column_index(column);
    return from_table(table, table_label, [c](const std::vector<double> &r) { return r[c]; });
  }

  double GridFunction::operator()(double x0) const
  {
    return value(&x0);
  }

  double GridFunction::operator()(double x0, double x1) const
  {
    const double x[2] = {x0, x1};
    return value(x);
  }

  double GridFunction::operator()(double x0, double x1, double x2) const
  {
    const double x[3] = {x0, x1, x2};
    return value(x);
  }

  double GridFunction::value(const double *x) const
  {
    Segment segments[3];
    for (unsigned int a = 0; a < axes.size(); ++a)
      segments[a] = segment(a, x[a]);
    return interpolate(0, 0, segments);
  }

  GridFunction::Segment GridFunction::segment(unsigned int a, double xq) const
  {
    const std::vector<double> &g = axes[a];
    const std::size_t n = g.size();
    const double tolerance = 1e-9 * (g.back() - g.front());
    if (!(xq >= g.front() - tolerance && xq <= g.back() + tolerance))
      throw TableRangeError(label + ": " + axis_names[a] + " = " + format_number(xq) +
                            " is outside the table's range [" + format_number(g.front()) + ", " +
                            format_number(g.back()) + "]");
    xq = std::clamp(xq, g.front(), g.back());
    std::size_t i = static_cast<std::size_t>(std::upper_bound(g.begin(), g.end(), xq) - g.begin());
    i = std::clamp<std::size_t>(i, 1, n - 1) - 1; // segment [g[i], g[i+1]]
    return {xq, i, i > 0 ? i - 1 : i, std::min(i + 2, n - 1)};
  }

  double GridFunction::interpolate(unsigned int a, std::size_t offset, const Segment *segments) const
  {
    const std::vector<double> &g = axes[a];
    const std::size_t n = g.size();
    const double xq = segments[a].x;
    const std::size_t i = segments[a].i, first = segments[a].first, last = segments[a].last;
    const double h = g[i + 1] - g[i];

    // The last axis: the tabulated values and their slopes along it (set once, in the constructor).
    if (a + 1 == axes.size())
      {
        const std::size_t k0 = offset + i * strides[a], k1 = k0 + strides[a];
        if (n == 2)
          return values[k0] + (values[k1] - values[k0]) / h * (xq - g[i]);
        return hermite((xq - g[i]) / h, h, values[k0], values[k1], last_axis_slopes[k0], last_axis_slopes[k1]);
      }

    // Values at the nodes i-1 .. i+2 that exist, interpolated along the remaining axes.
    double y[4] = {0, 0, 0, 0};
    for (std::size_t j = first; j <= last; ++j)
      y[j - first] = interpolate(a + 1, offset + j * strides[a], segments);
    const std::size_t li = i - first; // local index of g[i]
    const std::size_t m = last - first + 1;
    if (m == 2)
      return y[li] + (y[li + 1] - y[li]) / h * (xq - g[i]);
    const double *xs = g.data() + first;
    const double m0 = node_slope(xs, y, m, li, first == 0, last == n - 1);
    const double m1 = node_slope(xs, y, m, li + 1, first == 0, last == n - 1);
    return hermite((xq - g[i]) / h, h, y[li], y[li + 1], m0, m1);
  }
} // namespace servodrift
