#pragma once
// What measured data determine of a calibration's free parameters (issue 26): the rank of the
// Jacobian, the parameters the data cannot tell apart, and the combinations of those that they do
// determine, with their standard errors. Linear algebra on the Jacobian alone (Eigen).
#include "system/calibration.h"

#include <Eigen/Dense>

#include <vector>

namespace servodrift::system
{
  /// The residuals' Jacobian in the free parameters' scaled form, a row per measured value (the
  /// layout Ceres writes).
  using Jacobian = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

  /// What the data determine: the singular value decomposition of the Jacobian with unit columns
  /// (scale-free). A direction whose singular value is below 1e-6 of the largest changes the fit
  /// less than 1e-12 of the others: the data cannot see it, and the parameters that make it up
  /// (components above 0.1) cannot be told apart, or one does not act at all.
  struct Identifiability
  {
    Eigen::VectorXd column_norm;       ///< of the Jacobian's columns
    Eigen::VectorXd singular_values;
    Eigen::MatrixXd directions;        ///< V, in unit-column coordinates
    std::vector<Eigen::Index> lost;    ///< the directions the data cannot see
    std::vector<bool> identifiable;
    std::size_t rank;
  };

  Identifiability identifiability(const Jacobian &J);

  /// The combinations of the not-identifiable parameters orthogonal to the lost directions
  /// (restricted to them): what the data determine of them, with the standard error from the
  /// pseudo-inverse of the Jacobian's normal matrix (the lost directions left out), times the
  /// residuals' variance `variance' where sigma is estimated. `scale': the parameters' scales
  /// (value = initial + scale x); `estimates': their estimates.
  std::vector<DeterminedCombination> determined_combinations(const Identifiability &id,
                                                             const std::vector<FreeParameter> &parameters,
                                                             const std::vector<double> &scale,
                                                             const std::vector<double> &estimates, double variance);
} // namespace servodrift::system
