// The surfaces' shared part (values at the ends of a range, the command line of a surface run) and
// the dynamics mutations; the tolerance and calibration mutations are in their own files.
#include "fuzz_surfaces.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <set>

namespace fuzz
{
  namespace
  {
    /// Just beyond x in direction `dir' (+1, -1): the next double half the time (the least step a
    /// range check can miss), a visible 0.1 % otherwise; from zero a tiny or subnormal number.
    double beyond(Rng &rng, double x, double dir)
    {
      if (x == 0)
        return dir * (rng.coin() ? 1e-300 : std::numeric_limits<double>::denorm_min());
      if (rng.coin())
        return std::nextafter(x, dir * std::numeric_limits<double>::infinity());
      return x + dir * std::abs(x) * 1e-3;
    }

    /// Entries whose upper end is valid but slow (thousands of valves or steps): not drawn as such.
    const std::set<std::string> costly_entries{
      "Tolerances/Samples",         "Tolerances/Sobol base samples", "Tolerances/Bootstrap size",
      "Dynamics/Frequency points",  "Dynamics/Samples per period",   "Dynamics/Maximum periods",
      "Dynamics/Step duration",     "Dynamics/Reading times",        "Dynamics/Large-signal temperatures"};
  } // namespace

  Replacement range_value(Rng &rng, const Range &r, bool costly_end)
  {
    double x = 0;
    std::string label;
    // the ends themselves and just inside them reach the physics; beyond them only the range check
    switch (rng.below(costly_end ? 5 : 8))
      {
        case 0:
        case 1: x = r.lo, label = "lower end"; break;
        case 2: x = r.integer ? r.lo + 1 : beyond(rng, r.lo, +1), label = "just inside the lower end"; break;
        case 3: x = r.integer ? r.lo - 1 : beyond(rng, r.lo, -1), label = "below the lower end"; break;
        case 4:
          if (rng.below(4) == 0)
            x = rng.coin() ? -1e308 : 1e308, label = "far beyond";
          else
            x = r.integer ? r.hi + 1 : beyond(rng, r.hi, +1), label = "above the upper end";
          break;
        case 5:
        case 6: x = r.hi, label = "upper end"; break;
        default: x = r.integer ? r.hi - 1 : beyond(rng, r.hi, -1), label = "just inside the upper end";
      }
    std::string v = format_double(x);
    if (r.list)
      switch (rng.below(4))
        {
          case 0: v = v + ", " + v, label += ", twice"; break;
          case 1: v = format_double(r.hi) + ", " + format_double(r.lo), label = "the ends, decreasing"; break;
          case 2: v = format_double(r.lo) + ", " + format_double(r.hi), label = "both ends"; break;
          default: break;
        }
    return {v, label + " `" + shown(v) + "'"};
  }

  std::vector<std::string> ranged_entries(const Context &c, const std::string &prefix)
  {
    std::vector<std::string> found;
    for (const auto &[path, range] : c.ranges)
      if (path.rfind(prefix, 0) == 0)
        found.push_back(path);
    return found;
  }

  Setting range_setting(Rng &rng, const Context &c, const std::string &path, std::string &label)
  {
    const auto r = c.ranges.find(path);
    const Replacement v = r != c.ranges.end() ? range_value(rng, r->second, costly_entries.count(path) > 0)
                                              : bad_value(rng, "1", c.values);
    label = "`" + path + "' = " + v.label;
    return {path, v.value};
  }

  Setting valve_range_setting(Rng &rng, const Context &c, std::string &label)
  {
    // the subsections the system model reads beside the tables (not the solver, outputs or studies)
    std::vector<std::string> pool;
    for (const char *s : {"Operating conditions/", "Sweeps/", "Fluid/", "Armature/", "Thermal expansion/", "Pilot stage/",
                          "Spring tube/", "Torque motor/", "Offsets/", "Asymmetry/", "Spool/"})
      for (const auto &p : ranged_entries(c, s))
        pool.push_back(p);
    return range_setting(rng, c, rng.pick(pool), label);
  }

  std::string broken_table(Rng &rng, const Context &c, Mutation &m)
  {
    if (c.tables.empty())
      return "no table to break";
    std::vector<std::string> names;
    for (const auto &[name, content] : c.tables)
      names.push_back(name);
    const std::string &name = rng.pick(names);
    std::string t = m.out_files.count(name) ? m.out_files.at(name) : c.tables.at(name), what; // broken once more
    // the lines that hold data: of a CSV table those after the comments and the header, of fits.json
    // those with a coefficient
    const bool json = name.size() > 5 && name.compare(name.size() - 5, 5, ".json") == 0;
    std::vector<std::size_t> starts;
    for (std::size_t k = 0; k < t.size();)
      {
        const std::size_t e = std::min(t.find('\n', k), t.size());
        const std::string line = t.substr(k, e - k);
        if (json ? line.find("\"coefficient\": ") != std::string::npos
                 : !line.empty() && (std::isdigit(static_cast<unsigned char>(line[0])) || line[0] == '-'))
          starts.push_back(k);
        k = e + 1;
      }
    const auto line_end = [&](std::size_t k) { return std::min(t.find('\n', k), t.size()); };
    // no "nan" or "inf" token: on exit 0 the checks would take the driver's own for the product's
    const std::vector<std::string> numbers{"1e999", "-1e999", "1e308", "-1e308", "1e-320", "", "x", "0x1p3", "1,2"};
    switch (starts.empty() ? 4 : rng.below(6))
      {
        case 0:
          {
            // one number of a data line (JSON: a coefficient) replaced
            const std::size_t line = rng.pick(starts), e = line_end(line);
            std::vector<std::size_t> cells{json ? t.find(": ", line) + 2 : line};
            for (std::size_t k = t.find(',', line); !json && k < e; k = t.find(',', k + 1))
              cells.push_back(k + 1);
            const std::size_t k = rng.pick(cells), end = std::min(t.find(',', k), e);
            const std::string v = rng.pick(numbers);
            what = "a cell `" + shown(t.substr(k, end - k)) + "' -> `" + v + "'";
            t.replace(k, end - k, v);
            break;
          }
        case 1:
          {
            const std::size_t k = rng.pick(starts), e = line_end(k);
            what = "a data line deleted";
            t.erase(k, std::min(e + 1, t.size()) - k);
            break;
          }
        case 2:
          {
            const std::size_t k = rng.pick(starts), e = line_end(k);
            what = "a data line duplicated";
            t.insert(k, t.substr(k, e - k) + "\n");
            break;
          }
        case 3:
          {
            // a header line of the table's provenance changed: schema, rows, columns, units
            const std::vector<std::pair<std::string, std::string>> edits{
              {"# schema 1", "# schema 2"}, {"# rows ", "# rows 1"}, {"[degC]", "[K]"}, {"[N*m]", "[N*mm]"},
              {"temperature", "temperatur"}, {"\"coefficient\": ", "\"coefficient\": 1e999, \"x\": "}};
            const auto &[from, to] = rng.pick(edits);
            const std::size_t k = t.find(from);
            what = k == std::string::npos ? "unchanged (no `" + from + "')" : "`" + from + "' -> `" + to + "'";
            if (k != std::string::npos)
              t.replace(k, from.size(), to);
            break;
          }
        case 4:
          {
            const std::size_t k = rng.below(t.size());
            what = "truncated at byte " + std::to_string(k) + " of " + std::to_string(t.size());
            t.resize(k);
            break;
          }
        default:
          {
            const std::size_t k = rng.pick(starts);
            const std::string g = random_bytes(rng, 1 + rng.below(40), true);
            what = "bytes `" + shown(g) + "' inserted in a data line";
            t.insert(k, g);
          }
      }
    m.out_files[name] = t;
    return name + ": " + what;
  }

  bool bad_entry_under(Rng &rng, const Context &c, const std::vector<std::string> &prefixes,
                       std::vector<Setting> &hostile, std::vector<std::string> &labels)
  {
    std::vector<std::size_t> pool;
    for (auto e : c.prm.entries)
      for (const auto &prefix : prefixes)
        if (c.prm.lines[e].path.rfind(prefix, 0) == 0)
          {
            pool.push_back(e);
            break;
          }
    if (pool.empty())
      return false;
    const PrmLine &l = c.prm.lines[rng.pick(pool)];
    const Replacement r = bad_value(rng, l.value, c.values);
    hostile.push_back({l.path, r.value});
    labels.push_back("`" + l.path + "' = " + r.label);
    return true;
  }

  void surface_args(Rng &rng, const Context &c, Mutation &m, const std::string &command,
                    const std::vector<std::string> &positionals, const std::vector<Setting> &base,
                    const std::vector<Setting> &hostile)
  {
    // the file forms carry the hostile values through the parameter reader, --set through its own path
    std::uint64_t form = rng.below(4); // 0, 1: --set only; 2: .prm file; 3: .json file
    // an argument may not exceed 128 KiB (Linux MAX_ARG_STRLEN): a longer value goes in the file
    if (form < 2 && std::any_of(hostile.begin(), hostile.end(), [](const Setting &h) { return h.second.size() > 100000; }))
      form = 2;
    std::vector<Setting> as_options;
    Prm prm = c.prm;
    std::map<std::size_t, std::pair<std::size_t, std::string>> json_edits; ///< begin -> end, text; an entry's last value
    const std::vector<JsonValue> json_values_found = form == 3 ? json_values(c.json_text) : std::vector<JsonValue>{};
    for (const auto &[path, value] : hostile)
      {
        bool in_file = false;
        if (form == 2)
          for (auto k : prm.entries)
            if (prm.lines[k].path == path)
              set_value(prm.lines[k], value), in_file = true;
        if (form == 3)
          for (const auto &v : json_values_found)
            if (v.path == path)
              json_edits[v.begin] = {v.end, json_string(value)}, in_file = true;
        if (!in_file)
          as_options.push_back({path, value});
      }
    std::string valve;
    if (form == 2)
      m.files[valve = "input.prm"] = prm.text();
    else if (form == 3)
      {
        // edits from the back, so that the earlier positions stay right
        std::string json = c.json_text;
        for (auto e = json_edits.rbegin(); e != json_edits.rend(); ++e)
          json = json.substr(0, e->first) + e->second.second + json.substr(e->second.first);
        m.files[valve = "input.json"] = json;
      }

    m.args = {command};
    m.args.insert(m.args.end(), positionals.begin(), positionals.end());
    const bool valve_last = !valve.empty() && rng.coin(); // the usage allows it after the options
    if (!valve.empty() && !valve_last)
      m.args.push_back(valve);
    m.args.insert(m.args.end(), {"-o", "out"});
    const auto add = [&](const std::string &path, const std::string &value) {
      m.args.insert(m.args.end(), {"--set", path + "=" + value});
    };
    for (const auto &s : c.fixed_sets)
      m.args.insert(m.args.end(), {"--set", s});
    for (const auto &[path, value] : base)
      if (std::none_of(hostile.begin(), hostile.end(), [&](const Setting &h) { return h.first == path; }))
        add(path, value);
    for (const auto &[path, value] : as_options)
      add(path, value);
    if (valve_last)
      m.args.push_back(valve);
    m.description += std::string(form < 2 ? " (as --set)" : form == 2 ? " (in input.prm)" : " (in input.json)");
  }

  Mutation dynamics_mutation(Rng &rng, const Context &c)
  {
    Mutation m;
    m.category = dynamics_category;
    m.tables = true;
    // a run of about a second: one sine frequency and amplitude, the large-signal study at one temperature
    const std::vector<Setting> base{{"Sweeps/Drift temperatures", "40, 80, 120"},
                                    {"Dynamics/Large-signal temperatures", "1"},
                                    {"Dynamics/Sine frequencies", "100"},
                                    {"Dynamics/Sine amplitudes", "0.25"},
                                    {"Dynamics/Frequency points", "20"}};
    std::vector<Setting> hostile;
    std::vector<std::string> labels;
    const auto set = [&](const std::string &path, const std::string &value) {
      hostile.push_back({path, value});
      labels.push_back("`" + path + "' = `" + shown(value) + "'");
    };
    const auto ranged = [&](const std::string &prefix) {
      const std::vector<std::string> entries = ranged_entries(c, prefix);
      if (entries.empty())
        return;
      std::string label;
      hostile.push_back(range_setting(rng, c, rng.pick(entries), label));
      labels.push_back(label);
    };
    // mostly one hostile entry: a second one's range check would often hide the first one's effect
    const int n = rng.below(3) ? 1 : 2;
    for (int k = 0; k < n; ++k)
      switch (rng.below(12))
        {
          case 10: labels.push_back("broken table " + broken_table(rng, c, m)); break;
          case 11:
            {
              std::string label;
              hostile.push_back(valve_range_setting(rng, c, label));
              labels.push_back(label);
              break;
            }
          case 0:
          case 1: ranged("Dynamics/"); break;
          case 2:
          case 3: ranged("Spool/"); break;
          case 4:
            // the lap leakage's floor at and beyond its ends, with a spool that has no overlap
            set("Spool/Minimum leak length", rng.pick(std::vector<std::string>{"1e-9", "1e-10", "0.01", "9.999999e-10", "0"}));
            if (rng.coin())
              set("Spool/Overlap", rng.pick(std::vector<std::string>{"0", "1e-12", "0.01"}));
            break;
          case 5:
            {
              // tiny tolerances and few steps: the integrator must stop with a message, not run away
              const std::vector<Setting> tiny{{"Dynamics/Relative tolerance", "1e-14"}, {"Dynamics/Absolute tolerance", "1e-16"},
                                              {"Dynamics/Periodic tolerance", "1e-12"}, {"Dynamics/Maximum steps", "100"},
                                              {"Dynamics/Relative tolerance", "1e-15"}, {"Dynamics/Absolute tolerance", "0"}};
              const Setting &s = rng.pick(tiny);
              set(s.first, s.second);
              if (rng.coin())
                {
                  const Setting &t = rng.pick(tiny);
                  set(t.first, t.second);
                }
              break;
            }
          case 6:
            // the bias at and beyond its ends, a step or sine that takes it further
            set("Dynamics/Bias", rng.pick(std::vector<std::string>{"1", "-1", "0", "1e-9", "-1e-9", "0.999999", "1.0000001", "-1.5"}));
            if (rng.coin())
              set(rng.coin() ? "Dynamics/Small step" : "Dynamics/Sine amplitudes", rng.pick(std::vector<std::string>{"1", "1e-6", "100"}));
            break;
          case 7:
            {
              // lists out of order, repeated or empty; frequency bounds crossed
              const std::vector<Setting> lists{
                {"Dynamics/Sine frequencies", "200, 100"},   {"Dynamics/Sine frequencies", "100, 100"},
                {"Dynamics/Sine frequencies", "1e6"},        {"Dynamics/Sine frequencies", ""},
                {"Dynamics/Sine frequencies", "100,"},       {"Dynamics/Sine amplitudes", "1, 0.5"},
                {"Dynamics/Sine amplitudes", "1e-9"},        {"Dynamics/Sine amplitudes", "0.25, 0.25"},
                {"Dynamics/Minimum frequency", "1000"},      {"Dynamics/Maximum frequency", "1"},
                {"Dynamics/Maximum frequency", "0.001"},     {"Sweeps/Drift temperatures", "40"},
                {"Sweeps/Drift temperatures", "120, 40"},    {"Sweeps/Drift temperatures", "40, 40.000000000001"}};
              const Setting &s = rng.pick(lists);
              set(s.first, s.second);
              break;
            }
          case 8:
            // what the brake port feeds: a blocked port of no volume, a brake of none
            if (rng.coin())
              set("Spool/Brake port", "blocked-port"), set("Spool/Port volume", rng.pick(std::vector<std::string>{"0", "1e-15", "1"}));
            else
              set("Spool/Brake volume", rng.pick(std::vector<std::string>{"0", "1e-15", "1"}));
            break;
          default:
            bad_entry_under(rng, c, {"Dynamics/", "Spool/"}, hostile, labels);
        }
    for (std::size_t k = 0; k < labels.size(); ++k)
      m.description += (k ? "; " : "") + labels[k];
    surface_args(rng, c, m, "dynamics", {}, base, hostile);
    return m;
  }
} // namespace fuzz
