#pragma once
// Calibration (issue 26): the valve's uncertain parameters fitted to measured drift data by weighted
// nonlinear least squares on the system model (Ceres Solver: bounds, trust region, covariance),
// with standard errors, 95 % intervals, correlations, residuals, the reduced chi-square and the
// parameters the data cannot tell apart. doc/method.md "Calibration".
#include "common/valve_description.h"
#include "system/measured_data.h"
#include "system/stage_tables.h"
#include "system/tolerance_sampling.h"

#include <optional>
#include <string>
#include <vector>

namespace servodrift::system
{
  /// One free entry of the valve description, in its declared unit.
  struct FreeParameter
  {
    std::string path;             ///< "Subsection/Key"
    std::string unit;
    double initial, lower, upper; ///< start (the description's value) and bounds
  };

  struct CalibrationRequest
  {
    std::string measured_file;
    std::vector<std::string> free;       ///< "Subsection/Key" or "Subsection/Key=lower:upper"
    std::string input_file;              ///< the valve description the fit starts from
    std::vector<std::string> overrides;  ///< its --set overrides
  };

  /// The free parameters of `request' with their bounds, and the measured data, checked against the
  /// valve and its tables before anything runs (InputError naming the entry or the file and line).
  struct CalibrationSetup
  {
    std::vector<FreeParameter> parameters;
    MeasuredData data;
  };
  CalibrationSetup prepare_calibration(const CalibrationRequest &request, const StageTables &tables);

  /// The model along temperature for one measured series (quantity, current), for the plot.
  struct ModelCurve
  {
    MeasuredQuantity quantity;
    double current;                                   ///< [A]
    std::vector<double> temperatures, values, standard_deviations; ///< [degC], SI
  };

  /// A combination of entries the data cannot tell apart that they do determine (the direction of
  /// the fit orthogonal to the one they cannot see): sum_j coefficient_j x entry_j, the largest
  /// coefficient +-1, in the unit of its entry.
  struct DeterminedCombination
  {
    std::vector<std::string> paths;
    std::vector<double> coefficients;
    std::string unit;
    double estimate, standard_error;
    std::string text() const; ///< "`A' - 1.002 x `B'"
  };

  struct CalibrationResults
  {
    CalibrationRequest request;
    CalibrationSetup setup;
    std::vector<double> estimates;                      ///< declared units
    std::vector<std::optional<double>> standard_errors; ///< empty: not identifiable
    std::vector<std::optional<Interval>> intervals;     ///< at `confidence_level'
    std::vector<std::vector<double>> correlation;       ///< of the identifiable ones (0 elsewhere, 1 on the diagonal)
    double confidence_level = 0.95, interval_factor;    ///< z or Student's t
    std::vector<double> model;                          ///< at each measured point, SI
    std::vector<double> model_standard_deviation;       ///< from the parameters' covariance, SI
    std::vector<double> weights;                        ///< the sigma of each point, SI (given or estimated)
    double chi_square, reduced_chi_square;
    std::size_t degrees_of_freedom;                     ///< values - rank of the Jacobian
    std::size_t rank;                                   ///< directions the data determine
    bool sigma_estimated;                               ///< no standard deviations in the file
    std::vector<std::string> not_identifiable;          ///< paths the data cannot tell apart
    std::vector<DeterminedCombination> determined;      ///< what the data do determine of them
    std::vector<std::string> warnings;
    std::string termination;                            ///< Ceres' report, one line
    int iterations;
    std::vector<ModelCurve> curves;
    std::vector<std::string> calibrated_overrides;      ///< the request's overrides and the estimates
  };

  /// Fits the free parameters; `tables' are the valve's coefficient tables.
  CalibrationResults calibrate(const CalibrationRequest &request, const CalibrationSetup &setup,
                               const StageTables &tables);
} // namespace servodrift::system
