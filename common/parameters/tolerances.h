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
    double null_shift_spec;        ///< the spec's value: allowed |null-shift current| / rated current [1]
    /// How the allowed null shift depends on T: grows by null_shift_spec per 55 K from T0, is
    /// null_shift_spec everywhere, or follows null_shift_spec_table
    enum class SpecForm { per_55_kelvin, constant, table };
    SpecForm null_shift_spec_form;
    std::vector<std::pair<double, double>> null_shift_spec_table; ///< (T [degC], allowed / rated [1]), T increasing
    /// The allowed |null-shift current| / rated current at T [degC] for a valve nulled at T0 [degC];
    /// the table is interpolated linearly and held beyond its ends [1]
    double null_shift_limit(double T, double T0) const;
    /// Whether a null-shift current i [A] at T is within the spec, for the rated current and T0; a
    /// current below the null finder's resolution (1 nA) counts as none
    bool within_null_shift_spec(double i, double T, double rated_current, double T0) const;
    /// The spec in words, for reports: "2 % of rated per 55 K from 40 degC", ...
    std::string null_shift_spec_text(double T0) const;
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
