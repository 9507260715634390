#include "common/parameters/tolerances.h"

#include "common/parameters/parameter_helpers.h"

namespace servodrift
{
  using namespace parameters;

  void ToleranceParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    prm.declare_entry("Enabled", "false", Patterns::Bool(),
                      "Whether `servodrift run' does the tolerance study (`servodrift tolerances' always "
                      "does). [-]");
    prm.declare_entry("Samples", "1000", Patterns::Integer(1, 10000000),
                      "Valves of the Monte Carlo study, each nulled at the reference temperature by its "
                      "hydraulic null adjustment (D8). [1]");
    prm.declare_entry("Sampling", "monte-carlo",
                      Patterns::Selection("monte-carlo|latin-hypercube|randomised-sobol-sequence"),
                      "How the valves are drawn (OpenTURNS): independent draws (the yield's binomial "
                      "interval assumes these), Latin hypercube, or a randomised Sobol' sequence. [-]");
    prm.declare_entry("Seed", "1", Patterns::Integer(0, 2147483647),
                      "Seed of every random draw (samples, bootstrap): the same seed gives the same "
                      "results on any number of MPI ranks. [1]");
    prm.declare_entry("Null-shift spec", "2", Patterns::Double(0, 100),
                      "The null-shift spec in % of the rated current, > 0: with `Null-shift spec form' = "
                      "per-55K the allowed |null-shift current| grows by this much per 55 K from the "
                      "reference temperature, as catalogues quote it (typically 2 % per 55 K); with "
                      "constant, it is allowed at every drift temperature. [%]");
    prm.declare_entry("Null-shift spec form", "per-55K", Patterns::Selection("per-55K|constant|table"),
                      "How the allowed |null-shift current| depends on the temperature: per-55K, "
                      "`Null-shift spec' x |T - T0|/55 K; constant, `Null-shift spec'; table, `Null-shift "
                      "spec table'. The report and the tolerance study's yield hold the null shift against "
                      "it at every drift temperature. [-]");
    prm.declare_entry("Null-shift spec table", "-55: 4, 40: 0.5, 135: 4", Patterns::Anything(),
                      "With `Null-shift spec form' = table: `T: allowed' pairs, T in degC strictly "
                      "increasing and covering the drift temperatures, allowed |null-shift current| in % of "
                      "the rated current (>= 0), interpolated linearly in T. [degC: %]");
    prm.declare_entry("Sobol base samples", "512", Patterns::Integer(0, 1000000),
                      "N of the Sobol' design (N (d + 2) valves for d toleranced quantities): 0 (no "
                      "sensitivity study) or at least 64. [1]");
    prm.declare_entry("Sobol estimator", "martinez", Patterns::Selection("saltelli|jansen|martinez|mauntz-kucherenko"),
                      "Estimator of the first-order and total Sobol' indices (OpenTURNS). [-]");
    prm.declare_entry("Bootstrap size", "200", Patterns::Integer(10, 10000),
                      "Bootstrap resamples of the Sobol' indices' confidence intervals. Each costs about "
                      "30 ns per output and design valve: at the top of the range and the largest design "
                      "(`Sobol base samples' 1e6, 15 quantities) about 4 h. [1]");
    prm.declare_entry("Confidence level", "0.95", Patterns::Double(0.5, 0.9999),
                      "Level of every confidence interval (yield, Sobol' indices). [1]");
    prm.declare_entry("Correlations", "", Patterns::Anything(),
                      "Correlations of the Gaussian copula, `Quantity A : Quantity B : rho' separated by "
                      "commas, the quantities named as their subsections; the matrix must be positive "
                      "definite. Sobol' indices need independent quantities. [1]");
    for (const auto &[name, unit] : quantities())
      {
        prm.enter_subsection(name);
        prm.declare_entry("Distribution", "none", Patterns::Selection("none|normal|truncated-normal|uniform"),
                          "Distribution of the deviation of `" + name +
                            "' from the valve description's value; none: not toleranced. [-]");
        prm.declare_entry("Mean", "0", Patterns::Double(-1, 1),
                          "Mean of the deviation (normal, truncated normal before truncation). [" + unit + "]");
        prm.declare_entry("Standard deviation", "0", Patterns::Double(0, 1),
                          "Standard deviation of the deviation (normal, truncated normal before "
                          "truncation); must be > 0 for these. [" + unit + "]");
        prm.declare_entry("Lower bound", "0", Patterns::Double(-1, 1),
                          "Lower end of the deviation (uniform, truncated normal); must be <= 0, so that "
                          "the nominal valve is possible. [" + unit + "]");
        prm.declare_entry("Upper bound", "0", Patterns::Double(-1, 1),
                          "Upper end of the deviation (uniform, truncated normal); must be >= 0 and above "
                          "the lower bound. [" + unit + "]");
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }
} // namespace servodrift
