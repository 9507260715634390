#pragma once
// Sampling and estimators of the tolerance study, from libraries made for them (issue 25;
// doc/method.md "Tolerances"): OpenTURNS draws the valves (Monte Carlo, Latin hypercube, randomised
// Sobol' sequence, Gaussian copula for correlations), builds the Sobol' design and estimates the
// Sobol' indices with their bootstrap intervals and the quantiles; Boost gives the exact
// (Clopper-Pearson) interval of the yield. OpenTURNS headers stay in the .cc.
#include "common/parameters/tolerances.h"

#include <array>
#include <string>
#include <vector>

namespace servodrift::system
{
  using SampleRows = std::vector<std::vector<double>>; ///< one row per valve, one column per active quantity

  /// The valves of the Monte Carlo study: `samples' rows over the active quantities (deviations, SI).
  SampleRows draw_valves(const ToleranceParameters &tolerances);

  /// The Sobol' design of `Sobol base samples' N: N (d + 2) rows (blocks A, B, then A with column
  /// i of B, i = 1..d), for independent quantities.
  SampleRows sobol_design(const ToleranceParameters &tolerances);

  struct Interval
  {
    double lower, upper;
  };
  struct SobolIndices
  {
    std::vector<double> first_order, total;          ///< per active quantity [1]
    std::vector<Interval> first_order_interval, total_interval;
    /// Why the indices are undefined (the output's spread over the design is below its floor: no
    /// variance to share out, or only the solvers' round-off); empty when they are estimated
    std::string undefined;
    bool defined() const { return undefined.empty(); }
  };
  /// Indices of one output, from the design and its outputs (same row order), by the estimator of
  /// `tolerances' with its bootstrap intervals at its confidence level; undefined (and not
  /// estimated) when the output's standard deviation over the design is at most
  /// `standard_deviation_floor' (in the output's unit).
  SobolIndices sobol_indices(const ToleranceParameters &tolerances, const SampleRows &design, const std::vector<double> &output,
                             double standard_deviation_floor = 0);

  /// Empirical quantiles of `values' at probabilities `p' (OpenTURNS' estimator).
  std::vector<double> quantiles(const std::vector<double> &values, const std::vector<double> &p);

  /// Exact (Clopper-Pearson) two-sided interval of a proportion: `successes' of `trials' at `level'.
  Interval proportion_interval(std::size_t successes, std::size_t trials, double level);
} // namespace servodrift::system
