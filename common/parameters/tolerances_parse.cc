#include "common/parameters/tolerances.h"

#include "common/error.h"
#include "common/parameters/parameter_source.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
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

  double ToleranceParameters::null_shift_limit(double T, double T0) const
  {
    switch (null_shift_spec_form)
      {
        case SpecForm::constant: return null_shift_spec;
        case SpecForm::per_55_kelvin: return null_shift_spec * std::abs(T - T0) / 55;
        case SpecForm::table: break;
      }
    const auto &t = null_shift_spec_table;
    if (T <= t.front().first)
      return t.front().second;
    if (T >= t.back().first)
      return t.back().second;
    const auto hi = std::upper_bound(t.begin(), t.end(), T, [](double x, const auto &p) { return x < p.first; });
    const auto lo = hi - 1;
    return lo->second + (hi->second - lo->second) * (T - lo->first) / (hi->first - lo->first);
  }

  bool ToleranceParameters::within_null_shift_spec(double i, double T, double rated_current, double T0) const
  {
    constexpr double resolution = 1e-9; // [A] of the null finder
    return std::abs(i) <= null_shift_limit(T, T0) * rated_current + resolution;
  }

  std::string ToleranceParameters::null_shift_spec_text(double T0) const
  {
    const auto percent = [](double x) { return format_number(100 * x) + " %"; };
    switch (null_shift_spec_form)
      {
        case SpecForm::constant: return percent(null_shift_spec) + " of rated";
        case SpecForm::per_55_kelvin:
          return percent(null_shift_spec) + " of rated per 55 K from " + format_number(T0) + " degC";
        case SpecForm::table: break;
      }
    std::string text;
    for (const auto &[T, limit] : null_shift_spec_table)
      text += (text.empty() ? "" : ", ") + percent(limit) + " at " + format_number(T) + " degC";
    return text + " of rated (linear between)";
  }

  void ToleranceParameters::parse_parameters(ParameterSource &prm)
  {
    prm.enter_subsection(subsection);
    enabled = prm.get_bool("Enabled");
    samples = prm.get_integer("Samples");
    const std::string s = prm.get("Sampling");
    sampling = s == "latin-hypercube" ? Sampling::latin_hypercube :
               s == "randomised-sobol-sequence" ? Sampling::randomised_sobol_sequence : Sampling::monte_carlo;
    seed = prm.get_integer("Seed");
    null_shift_spec = prm.get_double("Null-shift spec") / 100;
    const std::string form = prm.get("Null-shift spec form");
    null_shift_spec_form = form == "constant" ? SpecForm::constant : form == "table" ? SpecForm::table : SpecForm::per_55_kelvin;
    null_shift_spec_table.clear();
    for (const std::string &pair : split_list(prm.get("Null-shift spec table"), ','))
      {
        const auto colon = pair.find(':');
        std::size_t used_T = 0, used_limit = 0;
        double T = 0, limit = 0;
        try
          {
            if (colon == std::string::npos)
              throw std::invalid_argument("no colon");
            T = std::stod(trimmed(pair.substr(0, colon)), &used_T);
            limit = std::stod(trimmed(pair.substr(colon + 1)), &used_limit);
          }
        catch (const std::exception &)
          {
            used_T = used_limit = 0;
          }
        if (used_T == 0 || used_T != trimmed(pair.substr(0, colon)).size() ||
            used_limit != trimmed(pair.substr(colon + 1)).size())
          throw InputError("`Tolerances/Null-shift spec table' has `" + trimmed(pair) +
                           "' (allowed: `T: allowed' pairs separated by commas, T in degC, allowed in % of rated)");
        null_shift_spec_table.emplace_back(T, limit / 100);
      }
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
    const bool any = !trimmed(text).empty();
    std::size_t position = 0;
    while (std::getline(items, item, ','))
      {
        ++position;
        if (trimmed(item).empty())
          refuse("has an empty item (item " + std::to_string(position) + ")");
        std::vector<std::string> parts;
        std::stringstream fields(item);
        for (std::string field; std::getline(fields, field, ':');)
          parts.push_back(trimmed(field));
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
