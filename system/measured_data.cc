#include "system/measured_data.h"

#include "common/error.h"
#include "common/output_files.h"
#include "common/parameter_input.h"

#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>
#include <sstream>

namespace servodrift::system
{
  const char *name(MeasuredQuantity q)
  {
    switch (q)
      {
        case MeasuredQuantity::null_shift_current: return "null_shift_current";
        case MeasuredQuantity::brake_pressure: return "brake_pressure";
        case MeasuredQuantity::control_pressure_difference: return "control_pressure_difference";
        case MeasuredQuantity::spool_displacement: return "spool_displacement";
        case MeasuredQuantity::spool_displacement_deviation: return "spool_displacement_deviation";
        case MeasuredQuantity::brake_pressure_deviation: return "brake_pressure_deviation";
      }
    return "?";
  }

  const char *si_unit(MeasuredQuantity q)
  {
    switch (q)
      {
        case MeasuredQuantity::null_shift_current: return "A";
        case MeasuredQuantity::spool_displacement:
        case MeasuredQuantity::spool_displacement_deviation: return "m";
        default: return "Pa";
      }
  }

  namespace
  {
    const std::vector<MeasuredQuantity> all_quantities = {
      MeasuredQuantity::null_shift_current,           MeasuredQuantity::brake_pressure,
      MeasuredQuantity::control_pressure_difference,  MeasuredQuantity::spool_displacement,
      MeasuredQuantity::spool_displacement_deviation, MeasuredQuantity::brake_pressure_deviation};

    /// Factor to SI of a unit a bench report may use for a quantity of SI unit `si'.
    std::optional<double> to_si(const std::string &unit, const std::string &si)
    {
      static const std::map<std::string, std::map<std::string, double>> units = {
        {"A", {{"A", 1}, {"mA", 1e-3}}},
        {"Pa", {{"Pa", 1}, {"kPa", 1e3}, {"MPa", 1e6}, {"bar", 1e5}}},
        {"m", {{"m", 1}, {"mm", 1e-3}, {"um", 1e-6}}},
        {"degC", {{"degC", 1}}}};
      const auto &known = units.at(si);
      const auto f = known.find(unit);
      return f == known.end() ? std::nullopt : std::optional<double>(f->second);
    }

    /// A bench's measured drift data are a few kB; anything near this is not such a file.
    constexpr std::size_t measured_file_bytes = 16u << 20;

    /// A standard deviation below this fraction of its value's size is below double precision: no
    /// model can meet it, and its weighted residual would overflow the least squares.
    constexpr double smallest_relative_standard_deviation = 1e-15;
    /// Nor below this in SI units (A, Pa, m), far under anything a bench resolves
    constexpr double smallest_standard_deviation = 1e-30;
    /// No measured quantity comes near this in SI units; beyond it squares (the least squares'
    /// chi-square) would overflow
    constexpr double largest_value = 1e100;

    std::string allowed_units(const std::string &si)
    {
      return si == "A" ? "A, mA" : si == "Pa" ? "Pa, kPa, MPa, bar" : si == "m" ? "m, mm, um" : "degC";
    }

    std::string trim(const std::string &s)
    {
      const auto b = s.find_first_not_of(" \t\r"), e = s.find_last_not_of(" \t\r");
      return b == std::string::npos ? "" : s.substr(b, e - b + 1);
    }

    /// What a header column is: "temperature[degC]", "<quantity>[unit]", "<quantity>_sd[unit]".
    struct Column
    {
      enum class Role { temperature, current, value, standard_deviation } role;
      MeasuredQuantity quantity;
      double factor; ///< to SI
    };
  } // namespace

  MeasuredData read_measured_data(const std::string &file)
  {
    std::istringstream in(read_text_file(file, "a measured-data CSV file", measured_file_bytes));
    MeasuredData data;
    data.file = file;
    std::string line;
    std::size_t number = 0;
    std::vector<Column> columns;
    const auto refuse = [&](std::size_t at, const std::string &what) {
      throw InputError(shown_input(file) + ":" + std::to_string(at) + ": " + what);
    };
    bool any_sd = false, missing_sd = false;
    std::map<std::pair<MeasuredQuantity, double>, std::pair<double, std::size_t>> series; ///< last T and its line
    while (std::getline(in, line))
      {
        ++number;
        const std::string t = trim(line);
        if (t.empty() || t[0] == '#')
          continue;
        std::vector<std::string> cells;
        std::stringstream items(t);
        for (std::string cell; std::getline(items, cell, ',');)
          cells.push_back(trim(cell));
        if (!t.empty() && t.back() == ',')
          cells.push_back("");
        if (columns.empty()) // the header
          {
            bool temperature = false, current = false;
            for (std::size_t c = 0; c < cells.size(); ++c)
              {
                const std::string &h = cells[c];
                const auto open = h.find('[');
                if (open == std::string::npos || h.back() != ']')
                  refuse(number, "column " + std::to_string(c + 1) + " `" + shown_input(h, 40) +
                                   "' has no unit (allowed: name[unit], e.g. brake_pressure[MPa])");
                const std::string base = h.substr(0, open), unit = h.substr(open + 1, h.size() - open - 2);
                const auto unit_of = [&](const std::string &si) {
                  const auto f = to_si(unit, si);
                  if (!f)
                    refuse(number, "column `" + shown_input(h, 40) + "': unit `" + shown_input(unit, 20) +
                                     "' (allowed: " + allowed_units(si) + ")");
                  return *f;
                };
                if (base == "temperature")
                  columns.push_back({Column::Role::temperature, {}, unit_of("degC")}), temperature = true;
                else if (base == "current")
                  columns.push_back({Column::Role::current, {}, unit_of("A")}), current = true;
                else
                  {
                    const bool sd = base.size() > 3 && base.substr(base.size() - 3) == "_sd";
                    const std::string quantity = sd ? base.substr(0, base.size() - 3) : base;
                    bool known = false;
                    for (const MeasuredQuantity q : all_quantities)
                      if (quantity == name(q))
                        {
                          columns.push_back({sd ? Column::Role::standard_deviation : Column::Role::value, q, unit_of(si_unit(q))});
                          known = true;
                        }
                    if (!known)
                      refuse(number, "column `" + shown_input(h, 40) +
                                       "' is not a measured quantity (allowed: temperature[degC], current[A], "
                                       "null_shift_current, brake_pressure, control_pressure_difference, "
                                       "spool_displacement and the _deviation of the last and of brake_pressure, "
                                       "each optionally with <name>_sd)");
                  }
              }
            if (!temperature || !current)
              refuse(number, std::string("the header has no `") + (temperature ? "current[A]" : "temperature[degC]") +
                               "' column");
            continue;
          }
        if (cells.size() != columns.size())
          refuse(number, std::to_string(cells.size()) + " cells where the header has " + std::to_string(columns.size()));
        double T = 0, i = 0;
        std::map<MeasuredQuantity, double> values, sds;
        for (std::size_t c = 0; c < cells.size(); ++c)
          {
            if (cells[c].empty())
              {
                if (columns[c].role == Column::Role::temperature || columns[c].role == Column::Role::current)
                  refuse(number, "column " + std::to_string(c + 1) + ": the temperature and the current must be given");
                continue;
              }
            char *end = nullptr;
            const double x = std::strtod(cells[c].c_str(), &end);
            if (end == cells[c].c_str() || *end != '\0' || !std::isfinite(x))
              refuse(number, "column " + std::to_string(c + 1) + ": `" + shown_input(cells[c], 30) +
                               "' is not a finite number");
            const double v = x * columns[c].factor;
            if (!(std::abs(v) <= largest_value))
              refuse(number, "column " + std::to_string(c + 1) + ": `" + shown_input(cells[c], 30) + "' " +
                               (std::isfinite(v) ? "is " + format_number(v) + " in SI units" : "overflows in SI units") +
                               " (allowed: at most 1e100 in magnitude)");
            switch (columns[c].role)
              {
                case Column::Role::temperature: T = v; break;
                case Column::Role::current: i = v; break;
                case Column::Role::value: values[columns[c].quantity] = v; break;
                case Column::Role::standard_deviation:
                  if (!(v > 0))
                    refuse(number, "column " + std::to_string(c + 1) + ": a standard deviation must be > 0");
                  sds[columns[c].quantity] = v;
                  break;
              }
          }
        for (const auto &[q, v] : values)
          {
            const auto sd = sds.find(q);
            (sd == sds.end() ? missing_sd : any_sd) = true;
            if (sd != sds.end() &&
                !(sd->second >= smallest_standard_deviation && sd->second >= smallest_relative_standard_deviation * std::abs(v)))
              refuse(number, std::string("the standard deviation of ") + name(q) + " is " + format_number(sd->second) + " " +
                               si_unit(q) + ", below double precision of its value " + format_number(v) +
                               " (allowed: at least 1e-15 of the value and 1e-30 " + si_unit(q) + ")");
            // a series (quantity, current) is measured at strictly increasing temperatures
            const auto key = std::make_pair(q, i);
            if (const auto last = series.find(key); last != series.end() && !(T > last->second.first))
              refuse(number, std::string("temperature ") + format_number(T) + " degC of " + name(q) + " at " +
                               format_number(i) + " A " + (T == last->second.first ? "repeats" : "is below") +
                               " line " + std::to_string(last->second.second) +
                               "'s (allowed: each series measured at increasing temperatures, each once)");
            series[key] = {T, number};
            data.points.push_back({number, T, i, q, v, sd == sds.end() ? 0.0 : sd->second});
          }
      }
    if (columns.empty())
      throw InputError(shown_input(file) + ": no header line (allowed: temperature[degC],current[A],<quantity>[unit],...)");
    if (data.points.empty())
      throw InputError(shown_input(file) + ": no measured values");
    if (any_sd && missing_sd)
      throw InputError(shown_input(file) + ": some values have a standard deviation and some do not (give one for "
                                           "every value, or none: then it is estimated from the fit)");
    data.standard_deviations_given = any_sd;
    return data;
  }
} // namespace servodrift::system
