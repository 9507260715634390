#include "common/grid_function.h"

#include "common/error.h"
#include "common/table.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace servodrift
{
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
  } // namespace

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
    if (a == axes.size())
      return values[offset];
    const std::vector<double> &g = axes[a];
    const std::size_t n = g.size();
    const double xq = segments[a].x;
    const std::size_t i = segments[a].i, first = segments[a].first, last = segments[a].last;

    // Values at the nodes i-1 .. i+2 that exist, interpolated along the remaining axes.
    double y[4] = {0, 0, 0, 0}, xs[4] = {0, 0, 0, 0};
    for (std::size_t j = first; j <= last; ++j)
      {
        y[j - first] = interpolate(a + 1, offset + j * strides[a], segments);
        xs[j - first] = g[j];
      }
    const std::size_t li = i - first; // local index of g[i]
    const std::size_t m = last - first + 1;
    const double h = xs[li + 1] - xs[li];
    const double d = (y[li + 1] - y[li]) / h;
    if (m == 2)
      return y[li] + d * (xq - xs[li]);

    auto secant = [&](std::size_t k) { return (y[k + 1] - y[k]) / (xs[k + 1] - xs[k]); };
    auto width = [&](std::size_t k) { return xs[k + 1] - xs[k]; };
    auto slope_at = [&](std::size_t k) {
      if (k == 0) // first node of the stencil: a grid end only if it is g[0]
        return first == 0 ? end_slope(width(0), width(1), secant(0), secant(1)) : 0.0;
      if (k == m - 1)
        return last == n - 1 ? end_slope(width(k - 1), width(k - 2), secant(k - 1), secant(k - 2)) : 0.0;
      return interior_slope(width(k - 1), width(k), secant(k - 1), secant(k));
    };
    const double m0 = slope_at(li), m1 = slope_at(li + 1);
    const double t = (xq - xs[li]) / h;
    const double t2 = t * t, t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * y[li] + (t3 - 2 * t2 + t) * h * m0 + (-2 * t3 + 3 * t2) * y[li + 1] +
           (t3 - t2) * h * m1;
  }
} // namespace servodrift
