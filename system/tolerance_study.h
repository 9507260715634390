#pragma once
// The tolerance study (issue 25): valves drawn from the manufacturing tolerances, each nulled at
// T0 and evaluated for its thermal null shift over the drift temperatures (Monte Carlo: drift
// envelopes, yield against the spec), and the Sobol' indices of which tolerance drives it. The
// valves are independent cases shared over the MPI ranks by the sweep runner.
#include "common/parameters/output.h"
#include "system/thermal_null_shift.h"
#include "system/tolerance_sampling.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace servodrift::system
{
  /// Summary statistics of one measure (at one temperature, or over the range).
  struct MeasureStatistics
  {
    std::string measure, unit;
    std::optional<double> temperature;     ///< [degC]; empty: over the drift temperatures
    double mean, standard_deviation;
    std::vector<double> quantiles;         ///< at ToleranceResults::probabilities
  };

  struct SobolStudy
  {
    unsigned int base_samples;              ///< N
    std::size_t evaluations;                ///< N (d + 2)
    std::vector<std::string> outputs;       ///< names of the outputs analysed
    std::vector<SobolIndices> indices;      ///< per output
    std::vector<double> output_variance;    ///< per output, over the design's A block
    double standard_deviation_floor;        ///< below it an output's indices are undefined (its unit)
  };

  struct ToleranceResults
  {
    std::vector<std::size_t> quantities;    ///< the active quantities (ToleranceParameters::quantities())
    std::vector<double> temperatures;       ///< drift temperatures [degC]
    double rated_current;                   ///< [A]
    std::string spec_text;                  ///< the null-shift spec in words
    std::vector<double> limits;             ///< allowed |null-shift current| / rated at each temperature [1]
    SampleRows inputs;                      ///< deviations of each valve (SI)
    std::vector<ThermalNullShift> valves;   ///< their thermal null shifts
    std::vector<bool> pass;                 ///< within the spec at every temperature
    std::size_t passes;
    Interval yield_interval;                ///< exact, at the confidence level
    double confidence_level;
    static inline const std::vector<double> probabilities = {0.01, 0.05, 0.5, 0.95, 0.99};
    std::vector<MeasureStatistics> statistics;   ///< over the valves within the tables
    std::size_t outside_tables = 0;             ///< valves the tables do not reach: failing, not evaluated
    std::string outside_example;                ///< the first of them: its largest deviation and why
    std::optional<SobolStudy> sobol;

    double yield() const { return double(passes) / double(valves.size()); }
  };

  /// The valve as described (Offsets and Asymmetry) with the deviations `row' of the quantities
  /// `quantities' added.
  Offsets built_valve(const ValveModel &model, const std::vector<std::size_t> &quantities, const std::vector<double> &row);

  /// `evaluate' on every row, over the MPI ranks; the outputs in row order on every rank.
  SampleRows evaluate_rows(const std::string &label, const SampleRows &rows,
                           const std::function<std::vector<double>(const std::vector<double> &)> &evaluate,
                           OutputParameters::Progress progress);

  /// The Sobol' study of any model of the active quantities (the valve's, or a test function):
  /// the design of `tolerances', `evaluate' on it, and the indices of each output whose standard
  /// deviation over the design exceeds `standard_deviation_floor' (the others undefined).
  SobolStudy sobol_study(const ToleranceParameters &tolerances, const std::vector<std::string> &outputs,
                         const std::function<std::vector<double>(const std::vector<double> &)> &evaluate,
                         OutputParameters::Progress progress, double standard_deviation_floor = 0);

  /// The whole study on the valve of `model' with the description's `Tolerances'.
  ToleranceResults compute_tolerances(const ValveModel &model, OutputParameters::Progress progress);
} // namespace servodrift::system
