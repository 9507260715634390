#include "common/parameters/tolerances.h"

#include "common/error.h"
#include "common/parameters/parameter_helpers.h"

#include <algorithm>
#include <sstream>

namespace servodrift
{
  using namespace parameters;

  const std::vector<std::pair<std::string, std::string>> &ToleranceParameters::quantities()
  {
    // name (the subsection) and the SI unit of its deviation; what each changes: system/build_deviations.cc
    static const std::vector<std::pair<std::string, std::string>> list = {
      {"Left orifice diameter", "m"},          {"Right orifice diameter", "m"},
      {"Left nozzle diameter", "m"},           {"Right nozzle diameter", "m"},
      {"Left null gap", "m"},                  {"Right null gap", "m"},
      {"Left orifice discharge factor", "1"},  {"Right orifice discharge factor", "1"},
      {"Left nozzle discharge factor", "1"},   {"Right nozzle discharge factor", "1"},
      {"Spring tube rest angle", "rad"},       {"Magnetic null", "rad"},
      {"Lower gap mismatch", "m"},             {"Left magnet remanence", "1"},
      {"Right magnet remanence", "1"}};
    return list;
  }

  std::vector<std::size_t> ToleranceParameters::active() const
  {
    std::vector<std::size_t> a;
    for (std::size_t k = 0; k < distributions.size(); ++k)
      if (distributions[k].kind != ToleranceDistribution::Kind::none)
        a.push_back(k);
    return a;
  }

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
                      "Allowed |null-shift current| over the drift temperatures, relative to the "
                      "reference temperature, in % of the rated current; must be > 0. Catalogues quote "
                      "about 2 % per 55 K. [%]");
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

  namespace
  {
    std::string trim(const std::string &s)
    {
      const auto b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
      return b == std::string::npos ? "" : s.substr(b, e - b + 1);
    }
  } // namespace

  void ToleranceParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    enabled = prm.get_bool("Enabled");
    samples = prm.get_integer("Samples");
    const std::string s = prm.get("Sampling");
    sampling = s == "latin-hypercube" ? Sampling::latin_hypercube :
               s == "randomised-sobol-sequence" ? Sampling::randomised_sobol_sequence : Sampling::monte_carlo;
    seed = prm.get_integer("Seed");
    null_shift_spec = prm.get_double("Null-shift spec") / 100;
    sobol_base_samples = prm.get_integer("Sobol base samples");
    const std::string e = prm.get("Sobol estimator");
    sobol_estimator = e == "saltelli" ? SobolEstimator::saltelli :
                      e == "jansen"   ? SobolEstimator::jansen :
                      e == "martinez" ? SobolEstimator::martinez : SobolEstimator::mauntz_kucherenko;
    bootstrap_size = prm.get_integer("Bootstrap size");
    confidence_level = prm.get_double("Confidence level");
    distributions.clear();
    for (const auto &[name, unit] : quantities())
      {
        prm.enter_subsection(name);
        ToleranceDistribution d;
        d.name = name;
        d.unit = unit;
        const std::string kind = prm.get("Distribution");
        d.kind = kind == "normal"           ? ToleranceDistribution::Kind::normal :
                 kind == "truncated-normal" ? ToleranceDistribution::Kind::truncated_normal :
                 kind == "uniform"          ? ToleranceDistribution::Kind::uniform : ToleranceDistribution::Kind::none;
        d.mean = prm.get_double("Mean");
        d.standard_deviation = prm.get_double("Standard deviation");
        d.lower = prm.get_double("Lower bound");
        d.upper = prm.get_double("Upper bound");
        distributions.push_back(d);
        prm.leave_subsection();
      }
    // `A : B : rho, ...'
    correlations.clear();
    const std::string text = prm.get("Correlations");
    std::stringstream items(text);
    std::string item;
    const auto refuse = [](const std::string &what) {
      throw InputError("`Tolerances/Correlations' " + what +
                       " (allowed: `Quantity A : Quantity B : rho' separated by commas, rho in (-1, 1), the "
                       "quantities named as the subsections of `Tolerances')");
    };
    const bool any = !trim(text).empty();
    std::size_t position = 0;
    while (std::getline(items, item, ','))
      {
        ++position;
        if (trim(item).empty())
          refuse("has an empty item (item " + std::to_string(position) + ")");
        std::vector<std::string> parts;
        std::stringstream fields(item);
        for (std::string field; std::getline(fields, field, ':');)
          parts.push_back(trim(field));
        if (parts.size() != 3)
          refuse("has an item that is not `A : B : rho'");
        Correlation c{};
        for (int k = 0; k < 2; ++k)
          {
            std::size_t index = quantities().size();
            for (std::size_t q = 0; q < quantities().size(); ++q)
              if (quantities()[q].first == parts[k])
                index = q;
            if (index == quantities().size())
              refuse("names an unknown quantity `" + parts[k].substr(0, 60) + "'");
            (k == 0 ? c.first : c.second) = index;
          }
        if (c.first == c.second)
          refuse("correlates `" + parts[0] + "' with itself");
        try
          {
            std::size_t used = 0;
            c.coefficient = std::stod(parts[2], &used);
            if (used != parts[2].size())
              throw std::invalid_argument("trailing");
          }
        catch (const std::exception &)
          {
            refuse("has a coefficient that is not a number");
          }
        if (!(c.coefficient > -1 && c.coefficient < 1))
          refuse("has a coefficient outside (-1, 1)");
        for (const Correlation &earlier : correlations)
          if (std::minmax(earlier.first, earlier.second) == std::minmax(c.first, c.second))
            refuse("gives the pair `" + parts[0] + "' and `" + parts[1] + "' twice");
        correlations.push_back(c);
      }
    if (any && text.find_last_not_of(" \t") != std::string::npos && text[text.find_last_not_of(" \t")] == ',')
      refuse("ends with a comma (an empty item)");
    prm.leave_subsection();
  }
} // namespace servodrift
