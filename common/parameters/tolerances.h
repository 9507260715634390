#pragma once
#include <string>
#include <vector>
namespace dealii { class ParameterHandler; }
namespace servodrift { class ParameterSource; }

namespace servodrift
{
  /// One toleranced build quantity: a deviation from the valve description's own value (issue 25).
  struct ToleranceDistribution
  {
    enum class Kind { none, normal, truncated_normal, uniform };
    std::string name;   ///< the subsection, e.g. "Left orifice diameter"
    std::string unit;   ///< SI unit of the deviation
    Kind kind = Kind::none;
    double mean = 0, standard_deviation = 0; ///< normal, truncated normal (before truncation) [unit]
    double lower = 0, upper = 0;             ///< uniform, truncated normal [unit]
  };

  /// Subsection "Tolerances": the manufacturing tolerances of the asymmetric valve, the null-shift
  /// spec, and how the study samples them (Monte Carlo of the thermal null shift, yield, Sobol indices).
  struct ToleranceParameters
  {
    static constexpr const char *subsection = "Tolerances";
    /// The toleranced quantities, in this fixed order (one subsection each).
    static const std::vector<std::pair<std::string, std::string>> &quantities(); ///< name, SI unit

    bool enabled;                  ///< `servodrift run' does the study
    unsigned int samples;          ///< valves of the Monte Carlo study [1]
    enum class Sampling { monte_carlo, latin_hypercube, randomised_sobol_sequence };
    Sampling sampling;
    unsigned int seed;             ///< of every random draw: same seed, same results [1]
    double null_shift_spec;        ///< allowed |null-shift current| / rated current over the range [1]
    unsigned int sobol_base_samples; ///< N of the Sobol design N (d + 2); 0: no Sobol study [1]
    enum class SobolEstimator { saltelli, jansen, martinez, mauntz_kucherenko };
    SobolEstimator sobol_estimator;
    unsigned int bootstrap_size;   ///< resamples of the Sobol indices' confidence intervals [1]
    double confidence_level;       ///< of every interval [1]
    std::vector<ToleranceDistribution> distributions; ///< all quantities, in quantities() order
    struct Correlation
    {
      std::size_t first, second; ///< indices into distributions
      double coefficient;        ///< Pearson correlation of the Gaussian copula [1]
    };
    std::vector<Correlation> correlations;

    /// Indices of the quantities with a distribution: the inputs of the study.
    std::vector<std::size_t> active() const;

    static void declare_parameters(dealii::ParameterHandler &prm);
    void parse_parameters(ParameterSource &prm);
  };
} // namespace servodrift
