#pragma once
// The coefficient tables and the drift map for system tools without FMI (issue 64 item 6): as
// MATLAB MAT v5 structs (axes and N-D arrays, readable by MATLAB and scipy.io.loadmat) and as
// Modelica text tables (`#1', `double name(rows, cols)') for CombiTable1Ds/CombiTable2Ds.
#include "common/table.h"

#include <string>
#include <vector>

namespace servodrift
{
  /// Values on a full tensor grid: axes (the first fastest in `values', MATLAB's column-major order)
  /// and quantities.
  struct GriddedData
  {
    struct Axis
    {
      Column column;
      std::vector<double> values;
    };
    struct Quantity
    {
      Column column;
      std::vector<double> values; ///< size: the product of the axes' sizes; axis 0 fastest
    };
    std::string name; ///< a MATLAB and Modelica identifier: "torque_motor", "drift_map"
    std::string description;
    std::vector<Axis> axes;
    std::vector<Quantity> quantities;
  };

  /// A coefficient table on its grid (the schema's axes; every value column but the flag's
  /// numbers, which become a quantity too). Throws std::runtime_error if the rows are no full grid.
  GriddedData gridded(const Table &table);

  /// Writes `data' as one MAT v5 file, a struct per data set (fields: each axis, each quantity,
  /// `units', `description'), through a temporary file and the run's transaction.
  void write_mat(const std::string &path, const std::vector<GriddedData> &data);

  /// Writes `data' as one Modelica text table file: per data set with one axis a matrix
  /// [axis, quantities...] (CombiTable1Ds); with two axes a matrix per quantity with the second
  /// axis in the first row and the first in the first column (CombiTable2Ds); with three, one such
  /// matrix per value of the first axis, named <set>_<quantity>_<k>.
  void write_modelica(const std::string &path, const std::vector<GriddedData> &data);
} // namespace servodrift
