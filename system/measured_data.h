#pragma once
// Measured drift data for the calibration (issue 26): a CSV file with rows of temperature [degC],
// current [A] and one or more measured quantities with their units in the header, each optionally
// with a standard deviation column `<quantity>_sd[unit]'. Read and checked completely before anything
// runs; every refusal names the file, the line and the column.
#include <string>
#include <vector>

namespace servodrift::system
{
  enum class MeasuredQuantity
  {
    null_shift_current,          ///< the current that restores p_L = p_R [A]
    brake_pressure,              ///< p_B, gauge [Pa]
    control_pressure_difference, ///< p_L - p_R [Pa]
    spool_displacement,          ///< x_v [m]
    /// D9 deviations (E40): from the ideal valve (no offsets, no asymmetry) at the same temperature
    /// and current (as assembled), or from the same valve at the reference temperature (nulled at
    /// reference); the paper's drift measures
    spool_displacement_deviation, ///< [m]
    brake_pressure_deviation      ///< [Pa]
  };
  const char *name(MeasuredQuantity q);
  const char *si_unit(MeasuredQuantity q);

  struct Measurement
  {
    std::size_t line;            ///< in the file
    double temperature, current; ///< [degC], [A]
    MeasuredQuantity quantity;
    double value;                ///< SI
    double standard_deviation;   ///< SI; 0 when the file gives none (then estimated from the fit)
  };

  struct MeasuredData
  {
    std::string file;
    std::vector<Measurement> points;
    bool standard_deviations_given; ///< every point has one
  };

  /// Reads and checks `file'. Throws InputError naming the file, line and column.
  MeasuredData read_measured_data(const std::string &file);
} // namespace servodrift::system
