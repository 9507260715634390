// Valid measured drift data for the calibrate mutations, made by the product itself: a run with a
// known magnetic null, whose drift map gives the values a bench would measure.
#include "fuzz_measured.h"

#include <cstdio>
#include <map>
#include <sstream>

namespace fuzz
{
  std::string num(double x)
  {
    char b[40];
    std::snprintf(b, sizeof(b), "%.9g", x);
    return b;
  }

  std::string Measured::text() const
  {
    const auto line = [](const std::vector<std::string> &cells) {
      std::string s;
      for (std::size_t k = 0; k < cells.size(); ++k)
        s += (k ? "," : "") + cells[k];
      return s + "\n";
    };
    std::string s = "# measured drift of a valve (fuzz_inputs)\n" + line(header);
    for (const auto &row : rows)
      s += line(row);
    return s;
  }

  Measured valid_data(const Context &c, int form)
  {
    Measured d;
    const auto &T = c.measured_temperatures;
    if (form == 1)
      {
        d.header = {"temperature[degC]", "current[A]", "null_shift_current[A]"};
        for (std::size_t k = 0; k < T.size(); ++k)
          d.rows.push_back({num(T[k]), "0", num(c.measured_null_shift[k])});
        return d;
      }
    d.header = {"temperature[degC]", "current[mA]", "null_shift_current[mA]", "null_shift_current_sd[mA]"};
    if (form == 2)
      d.header.insert(d.header.end(), {"brake_pressure[MPa]", "brake_pressure_sd[MPa]"});
    for (std::size_t k = 0; k < T.size(); ++k)
      {
        d.rows.push_back({num(T[k]), "0", num(c.measured_null_shift[k] * 1e3), "0.0001"});
        if (form == 2)
          d.rows.back().insert(d.rows.back().end(), {"", ""});
      }
    if (form == 2) // the brake-pressure series at the rated current, its null-shift cells empty
      for (std::size_t k = 0; k < T.size(); ++k)
        d.rows.push_back({num(T[k]), num(c.rated_current * 1e3), "", "", num(c.measured_brake_pressure[k] * 1e-6), "0.001"});
    return d;
  }

  std::string make_measured_data(Context &c, const fs::path &work, double timeout, Outcome &o)
  {
    // a magnetic null of 0.02 degree, as tests/cli/calibrate_example.sh makes its data: the fit from 0
    // has something to find
    std::vector<std::string> args{c.servodrift, "run", "-o", "measured-source"};
    for (const auto &s : c.fixed_sets)
      args.insert(args.end(), {"--set", s});
    for (const char *s : {"Offsets/Magnetic null=0.02", "Sweeps/Deviation angles=0", "Sweeps/Drift temperatures=40, 60, 80, 100, 120"})
      args.insert(args.end(), {"--set", s});
    o = run_process(args, work, timeout);
    if (o.exit_code != 0)
      return "the run that makes the measured data for `calibrate' failed";
    std::istringstream in(read_file(work / "measured-source" / "system" / "drift_map.csv"));
    std::map<std::string, std::size_t> column;
    for (std::string line; std::getline(in, line);)
      {
        if (line.empty() || line[0] == '#')
          continue;
        std::vector<std::string> cells;
        std::istringstream items(line);
        for (std::string cell; std::getline(items, cell, ',');)
          cells.push_back(cell);
        if (column.empty()) // the header: names with units
          {
            for (std::size_t k = 0; k < cells.size(); ++k)
              column[cells[k].substr(0, cells[k].find('['))] = k;
            for (const char *name : {"temperature", "deviation_angle", "null_shift_current", "brake_pressure"})
              if (!column.count(name))
                return std::string("drift_map.csv has no column `") + name + "'";
            continue;
          }
        const auto cell = [&](const char *name) { return column[name] < cells.size() ? cells[column[name]] : ""; };
        // an empty null-shift current lies beyond the torque table: not a value a bench would report
        if (cell("null_shift_current").empty() || cell("brake_pressure").empty() || std::stod(cell("deviation_angle")) != 0)
          continue;
        c.measured_temperatures.push_back(std::stod(cell("temperature")));
        c.measured_null_shift.push_back(std::stod(cell("null_shift_current")));
        c.measured_brake_pressure.push_back(std::stod(cell("brake_pressure")));
      }
    if (c.measured_temperatures.size() < 3)
      return "drift_map.csv has fewer than 3 rows for the measured data";
    for (auto k : c.prm.entries)
      if (c.prm.lines[k].path == "Operating conditions/Rated current")
        c.rated_current = std::stod(c.prm.lines[k].value);
    return "";
  }
} // namespace fuzz
