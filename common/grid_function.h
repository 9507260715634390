#pragma once
// A function tabulated on a full tensor grid (1 to 3 axes), evaluated by monotone piecewise-cubic
// Hermite interpolation (PCHIP, Fritsch-Carlson slopes) along each axis in turn. It reproduces the
// table at its nodes, is continuous with a continuous first derivative along each axis wherever the
// data are monotone, and never overshoots the data (a flow conductance stays >= 0). A query outside
// the grid throws TableRangeError naming table, variable, value and range.
#include <functional>
#include <string>
#include <vector>

namespace servodrift
{
  class Table;

  class GridFunction
  {
  public:
    /// Axes: names with units for messages ("gap[m]"); values: row-major, last axis fastest.
    GridFunction(std::string table_label, std::vector<std::string> axis_names,
                 std::vector<std::vector<double>> axes, std::vector<double> values);

    /// From a table whose first n_axes columns form a full grid (any row order); value_of_row maps
    /// a row to the tabulated value. Throws InputError if the rows do not form a full grid.
    static GridFunction from_table(const Table &table, const std::string &table_label,
                                   const std::function<double(const std::vector<double> &row)> &value_of_row);
    /// Same, tabulating one column.
    static GridFunction from_table(const Table &table, const std::string &table_label, const std::string &column);

    unsigned int dimension() const { return static_cast<unsigned int>(axes.size()); }
    const std::vector<double> &axis(unsigned int k) const { return axes[k]; }
    const std::string &axis_name(unsigned int k) const { return axis_names[k]; }

    double operator()(double x0) const;
    double operator()(double x0, double x1) const;
    double operator()(double x0, double x1, double x2) const;
    double value(const double *x) const;

  private:
    std::string label;
    std::vector<std::string> axis_names;
    std::vector<std::vector<double>> axes;
    std::vector<double> values;
    std::vector<std::size_t> strides;
    std::vector<double> last_axis_slopes; ///< PCHIP slopes along the last axis at every node

    /// Where a query falls on one axis: the clamped coordinate, its segment [g[i], g[i+1]] and the
    /// nodes first..last of its PCHIP stencil. Found once per axis and query.
    struct Segment
    {
      double x;
      std::size_t i, first, last;
    };
    Segment segment(unsigned int axis, double x) const;
    double interpolate(unsigned int axis, std::size_t offset, const Segment *segments) const;
  };
} // namespace servodrift
