#pragma once
// Drift maps (model.md D8, D9, E40, C8): over temperature x assembly deviation angle, the spool
// displacement at i = 0 and the output (brake) pressure at the rated current, their deviations and
// tangent slopes, the null-shift current and the pilot null pressure shift.
#include "common/parameters/output.h"
#include "system/valve_model.h"

#include <optional>
#include <vector>

namespace servodrift::system
{
  struct DriftPoint
  {
    double temperature;     ///< [degC]
    double deviation_angle; ///< theta_d [rad]
    Offsets offsets;        ///< theta_s, theta_m, x_n of this valve (D8)
    OperatingPoint zero_current, rated_current;
    std::optional<double> null_shift_current; ///< [A]; empty beyond the torque table's currents

    // Deviations (E40) and slopes, by the nulling convention of the valve description (D9, C8)
    double spool_displacement_deviation;         ///< delta x_v at i = 0 [m]
    double spool_displacement_deviation_slope;   ///< d(delta x_v)/dT [m/degC]
    double brake_pressure_deviation;             ///< delta p_B at the rated current [Pa]
    double brake_pressure_deviation_slope;       ///< [Pa/degC]
    double brake_pressure_deviation_own_drift_removed; ///< C8: minus the theta_d = 0 valve's own drift [Pa]
    double null_pressure_shift;                  ///< p_L - p_R at i = 0 [Pa]
    /// The deviation crosses a regime boundary (flapper on a nozzle, spool on a stop, or a spool
    /// regime other than the reference point's): it measures the boundary, not the valve (C8).
    bool displacement_saturated;
    bool pressure_saturated;
  };

  struct DriftMap
  {
    std::vector<double> temperatures;     ///< [degC]
    std::vector<double> deviation_angles; ///< [rad]
    std::vector<DriftPoint> points;       ///< temperature-major: points[t * n_angles + a]
    bool nulled_at_reference;

    const DriftPoint &at(std::size_t t, std::size_t a) const { return points[t * deviation_angles.size() + a]; }
  };

  /// Computes the map over `Sweeps/Drift temperatures' x `Sweeps/Deviation angles'; the cases are
  /// shared over the MPI ranks. The reference temperature and theta_d = 0 are computed as well where
  /// a deviation needs them.
  DriftMap compute_drift_map(const ValveModel &model, OutputParameters::Progress progress);

  /// Derivative of y(x) on a non-uniform grid: three-point formulas, second order (secant for two
  /// points).
  std::vector<double> derivative_on_grid(const std::vector<double> &x, const std::vector<double> &y);
} // namespace servodrift::system
