// The calibration's mutations: a valid measured-data file (made by the model, doc/user-guide.md
// section 6) broken in one way (not a regular file, bytes, NUL, order, non-finite or overflowing
// numbers, standard deviations, rows, columns, units), or hostile --free entries and start values.
#include "fuzz_measured.h"
#include "fuzz_surfaces.h"

namespace fuzz
{
  namespace
  {
    std::string &any_cell(Rng &rng, Measured &d, bool numeric_only)
    {
      for (;;)
        {
          std::vector<std::string> &row = d.rows[rng.below(d.rows.size())];
          std::string &cell = row[rng.below(row.size())];
          if (!numeric_only || !cell.empty())
            return cell;
        }
    }
  } // namespace

  Mutation calibrate_mutation(Rng &rng, const Context &c)
  {
    Mutation m;
    m.category = calibrate_category;
    m.tables = true;
    if (c.measured_temperatures.empty())
      {
        m.args = {"calibrate", "--help"};
        m.description = "no measured data could be made: `calibrate --help' only";
        return m;
      }
    const int form = static_cast<int>(rng.below(3));
    Measured d = valid_data(c, form);
    std::string measured = "measured.csv", label;
    std::vector<std::string> free{"Offsets/Magnetic null"};
    std::vector<Setting> hostile;
    bool write = true, usage = false, refuse = true, valid = false;
    const std::size_t cols = d.header.size();
    switch (rng.below(29))
      {
        case 27:
        case 28:
          {
            // entries the data may not determine at all (a spool's, the fluid's): the fit's covariance
            // and standard errors must stay finite, or the run refuse
            refuse = false;
            std::vector<std::string> pool;
            for (const char *s : {"Offsets/", "Asymmetry/", "Spool/", "Operating conditions/", "Fluid/", "Armature/", "Thermal expansion/"})
              for (const auto &p : ranged_entries(c, s))
                if (!c.ranges.at(p).list && !c.ranges.at(p).integer)
                  pool.push_back(p);
            free.resize(1 + rng.below(3));
            for (auto &f : free)
              f = rng.pick(pool);
            label = "free entries the data may not determine";
            if (form == 1)
              d = valid_data(c, 2); // 10 values with standard deviations: enough for 3 free entries
            break;
          }
        case 25: refuse = false, label = "valid data, broken table " + broken_table(rng, c, m); break;
        case 26:
          refuse = false;
          hostile.push_back(valve_range_setting(rng, c, label));
          label = "valid data, " + label;
          break;
        case 0:
          {
            // not a regular file: the product must refuse at once (a FIFO without writer must not hang)
            write = false;
            switch (rng.below(5))
              {
                case 0: m.directory = measured, label = "measured file is a directory"; break;
                case 1: m.fifo = measured, label = "measured file is a FIFO with no writer"; break;
                case 2: measured = "/dev/zero", label = "measured file is /dev/zero"; break;
                case 3: measured = "/dev/null", label = "measured file is /dev/null"; break;
                default: measured = "absent.csv", label = "measured file does not exist";
              }
            break;
          }
        case 1:
          {
            write = false;
            const std::size_t n = 1 + rng.below(4096);
            m.files[measured] = random_bytes(rng, n, true);
            label = "measured file is " + std::to_string(n) + " random bytes";
            break;
          }
        case 2:
          {
            const std::string g = rng.coin() ? high_bytes(rng, 1 + rng.below(60)) : random_bytes(rng, 1 + rng.below(60), true);
            d.rows.insert(d.rows.begin() + rng.below(d.rows.size() + 1), {g});
            label = "a line of bytes `" + shown(g) + "' among the rows";
            // unless it is blank or a comment, or splits into lines that may be
            const std::string t = trim(g);
            refuse = g.find('\n') == std::string::npos && !t.empty() && t[0] != '#';
            break;
          }
        case 3:
          {
            std::string &cell = rng.coin() ? d.header[rng.below(cols)] : any_cell(rng, d, true);
            const std::size_t at = rng.below(cell.size() + 1);
            cell.insert(at, 1, '\0');
            label = "a NUL byte inside the cell `" + shown(cell) + "'";
            break;
          }
        case 4:
          {
            const std::size_t k = 1 + rng.below(d.rows.size() - 1);
            const bool repeat = rng.coin();
            d.rows[k][0] = repeat ? d.rows[k - 1][0] : num(std::stod(d.rows[k - 1][0]) - 1);
            label = std::string("row ") + std::to_string(k + 1) + (repeat ? " repeats" : " goes below") + " the temperature before it";
            break;
          }
        case 5:
          {
            std::string &cell = any_cell(rng, d, true);
            cell = rng.pick(std::vector<std::string>{"nan", "NaN", "-nan", "inf", "-inf", "Infinity", "1e999", "-1e400", "0x1p99999"});
            label = "a non-finite cell `" + cell + "'";
            break;
          }
        case 6:
          {
            // finite as written, beyond a double after the unit factor
            d.header = {"temperature[degC]", "current[mA]", "brake_pressure[" + rng.pick(std::vector<std::string>{"MPa", "bar", "kPa"}) + "]"};
            const std::vector<double> &pb = c.measured_brake_pressure;
            d.rows.clear();
            for (std::size_t k = 0; k < c.measured_temperatures.size(); ++k)
              d.rows.push_back({num(c.measured_temperatures[k]), num(c.rated_current * 1e3), num(pb[k] * 1e-6)});
            d.rows[rng.below(d.rows.size())][2] = rng.coin() ? "1e308" : "1.7976931348623157e308";
            label = "brake pressure 1e308 in " + d.header[2];
            break;
          }
        case 7:
          {
            if (form == 1)
              d = valid_data(c, 0);
            const std::string sd = rng.pick(std::vector<std::string>{"0", "-0", "-1", "1e-300", "4.9e-324", "1e-40", "nan"});
            d.rows[rng.below(c.measured_temperatures.size())][3] = sd; // a null-shift row in every form
            if (d.rows.size() > 5 && d.rows.back().size() > 5)
              d.rows.back()[5] = sd;
            label = "a standard deviation of " + sd;
            break;
          }
        case 8:
          {
            // fewer values than free entries (no standard deviations: the noise is estimated)
            d = valid_data(c, 1);
            d.rows.resize(1 + rng.below(2));
            free.push_back("Offsets/Hydraulic null");
            if (rng.coin())
              free.push_back("Asymmetry/Left orifice diameter deviation");
            refuse = d.rows.size() <= free.size();
            label = std::to_string(d.rows.size()) + " rows for " + std::to_string(free.size()) + " free entries";
            break;
          }
        case 9:
          switch (rng.below(6))
            {
              case 0: d.header.erase(d.header.begin()), label = "no temperature column"; for (auto &r : d.rows) r.erase(r.begin()); break;
              case 1: d.header.erase(d.header.begin() + 1), label = "no current column"; for (auto &r : d.rows) r.erase(r.begin() + 1); break;
              case 2: d.rows.clear(), label = "the header alone"; break;
              case 3: d.header = {"temperature[degC]", "current[A]"}, label = "no measured quantity"; for (auto &r : d.rows) r.resize(2); break;
              case 4: d.header = d.rows[0], label = "no header (a data row first)"; break;
              default: write = false, m.files[measured] = rng.coin() ? "" : "# only a comment\n", label = "empty or comments only";
            }
          break;
        case 10:
          {
            std::string &h = d.header[rng.below(cols)];
            const std::string unit = rng.pick(std::vector<std::string>{"[K]", "[degF]", "[]", "[MA]", "[ma]", "[ mA ]", "[\xc2\xb5" "A]", "[A][A]", ""});
            h = h.substr(0, h.find('[')) + unit;
            label = "column `" + shown(h) + "' (unknown or no unit)";
            break;
          }
        case 11:
          {
            auto &row = d.rows[rng.below(d.rows.size())];
            switch (rng.below(3))
              {
                case 0: row.push_back("1"), label = "a row with a cell too many"; break;
                case 1: row.pop_back(), label = "a row with a cell too few"; break;
                default: row[rng.below(2)] = "", label = "a row without its temperature or current";
              }
            break;
          }
        case 12:
          {
            refuse = false; // beyond the tables: a refusal is likely, but 39.999 degC may be fine
            const bool low = rng.coin(), temperature = rng.coin();
            auto &row = low ? d.rows.front() : d.rows.back();
            const std::vector<std::string> lows{"-273.15", "-300", "39.999", "-1e300"}, highs{"1000", "120.001", "1e300", "1001"};
            row[temperature ? 0 : 1] = temperature ? rng.pick(low ? lows : highs) : rng.pick(std::vector<std::string>{"1e3", "-1e3", "1e300"});
            label = std::string(temperature ? "temperature `" : "current `") + row[temperature ? 0 : 1] + "' beyond the tables";
            break;
          }
        case 13:
          if (form == 1)
            d = valid_data(c, 0);
          d.rows[rng.below(c.measured_temperatures.size())][3] = "";
          label = "one value without its standard deviation";
          break;
        case 14:
          {
            // data no magnetic null within +-10 degrees explains: the fit ends at a bound or refuses
            refuse = false;
            const double f = rng.pick(std::vector<double>{1e6, -1, 0, 1e-12});
            for (auto &row : d.rows)
              if (!row[2].empty())
                row[2] = num(std::stod(row[2]) * f);
            label = "null-shift currents x " + num(f);
            break;
          }
        case 15:
          {
            refuse = false;
            if (rng.below(3) == 0)
              {
                write = false;
                m.files[measured] = d.text() + std::string(17u << 20, '#');
                label = "a 17 MB file";
                break;
              }
            // 5000 rows at increasing temperatures, linearly between the data's
            d = valid_data(c, 1);
            const auto &T = c.measured_temperatures;
            const auto &I = c.measured_null_shift;
            d.rows.clear();
            for (int k = 0; k < 5000; ++k)
              {
                const double t = T.front() + (T.back() - T.front()) * k / 4999.0;
                std::size_t j = 0;
                while (j + 2 < T.size() && t > T[j + 1])
                  ++j;
                const double w = (t - T[j]) / (T[j + 1] - T[j]);
                d.rows.push_back({num(t), "0", num(I[j] + w * (I[j + 1] - I[j]))});
              }
            label = "5000 rows";
            break;
          }
        case 16:
          {
            write = false, refuse = false;
            std::string t = d.text();
            switch (rng.below(3))
              {
                case 0: t = "\xef\xbb\xbf" + t, label = "a UTF-8 byte-order mark first"; break;
                case 1:
                  for (std::size_t k = t.find('\n'); k != std::string::npos; k = t.find('\n', k + 2))
                    t.insert(k, 1, '\r');
                  label = "CRLF line ends";
                  break;
                default:
                  for (std::size_t k = t.find(','); k != std::string::npos; k = t.find(',', k + 3))
                    t.replace(k, 1, " ,\t");
                  label = "blanks around every cell";
              }
            m.files[measured] = t;
            break;
          }
        case 17:
          refuse = false;
          d.header.push_back(rng.coin() ? d.header[2] : "temperature_sd[degC]");
          for (auto &r : d.rows)
            r.push_back(r[2].empty() ? "1" : r[2]);
          label = "an extra column `" + d.header.back() + "'";
          break;
        case 18:
          free = {rng.pick(std::vector<std::string>{"Offsets/Magnetic nul", "Offsets", "Magnetic null", "", "=", "Offsets/Magnetic null/x",
                                                    "Offsets/Magnetic null=", "/Magnetic null", "Foo/Bar=1:2", "Offsets//Magnetic null"})};
          label = "--free `" + free[0] + "' (no such entry)";
          break;
        case 19:
          {
            const std::string b = rng.pick(std::vector<std::string>{"-11:11", "5:1", "1:1", "a:b", "nan:1", "-inf:inf", "1e308:1e309",
                                                                    "0.1:", ":0.1", "1:2:3", "-10:10", "-1e-320:1e-320"});
            free = {"Offsets/Magnetic null=" + b};
            refuse = b != "-10:10" && b != "-1e-320:1e-320";
            label = "--free bounds `" + b + "'";
            break;
          }
        case 20:
          free = {rng.pick(std::vector<std::string>{"Output/Plots", "Pilot stage/Model level", "Sweeps/Drift temperatures",
                                                    "Tolerances/Samples", "Dynamics/Enabled", "Output/Directory", "Tolerances/Correlations",
                                                    "Tolerances/Magnetic null/Standard deviation"})};
          refuse = free[0].rfind("Tolerances/", 0) != 0 || free[0] == "Tolerances/Correlations";
          label = "--free `" + free[0] + "' (not a numeric entry of the valve)";
          break;
        case 21:
          refuse = false;
          if (rng.coin())
            free.push_back(free[0]), label = "the same entry free twice";
          else
            {
              free.clear();
              for (const auto &p : ranged_entries(c, "Asymmetry/"))
                free.push_back(p);
              for (const auto &p : ranged_entries(c, "Offsets/"))
                free.push_back(p);
              label = std::to_string(free.size()) + " free entries";
            }
          break;
        case 22:
          {
            // a start far from the data, at the range end, or outside the free entry's own bounds
            refuse = false;
            const std::string start = rng.pick(std::vector<std::string>{"2", "-2", "10", "-10", "9.99", "1"});
            hostile.push_back({"Offsets/Magnetic null", start});
            if (rng.coin())
              free = {"Offsets/Magnetic null=-0.1:0.1"};
            label = "start `Offsets/Magnetic null' = " + start + " deg" + (free[0].size() > 21 ? ", bounds -0.1:0.1" : "");
            break;
          }
        case 23:
          {
            std::string why;
            hostile.push_back(range_setting(rng, c, rng.pick(ranged_entries(c, "Offsets/")), why));
            refuse = false;
            free = {"Offsets/Magnetic null", "Offsets/Spring tube rest angle"};
            label = "theta_m and theta_s free (not identifiable apart), " + why;
            break;
          }
        default:
          switch (rng.below(6))
            {
              case 4:
                {
                  // a name the refusal must not echo raw: a newline, Latin-1 bytes, 240 characters, a dash
                  const std::vector<std::string> names{"m\neasured.csv", "m\xe9sur\xe9.csv", std::string(240, 'm') + ".csv",
                                                       "-measured.csv", "no/such/dir/measured.csv", "measured.csv\r"};
                  measured = rng.pick(names);
                  write = measured.find('/') == std::string::npos;
                  usage = measured[0] == '-', refuse = !write || usage;
                  label = "measured file named `" + shown(measured) + "'";
                  break;
                }
              case 5:
                {
                  const std::vector<std::string> odd{"Offsets/Magnetic null\nOffsets/Spring tube rest angle", "Offsets/M\xe4gnetic null",
                                                     "Offsets/Magnetic null=\xff:\xfe", "Offsets/" + std::string(50000, 'x'),
                                                     "Offsets/Magnetic null=-1:" + std::string(50000, '1')};
                  free = {rng.pick(odd)};
                  label = "--free `" + shown(free[0]) + "'";
                  break;
                }
              case 0: usage = true, label = "no measured file on the command line"; break;
              case 1: free.clear(), refuse = false, label = "no --free entry"; break;
              case 2: refuse = false, label = "the valve file given as the measured data"; m.files[measured] = c.prm_text, write = false; break;
              default:
                refuse = false, valid = form != 2, label = "valid measured data";
            }
      }
    if (write)
      m.files[measured] = d.text();
    m.expect_refusal = refuse && !valid;
    m.expect_success = valid;
    m.usage_allowed = usage;
    m.description = label + (write ? " [" + std::to_string(d.rows.size()) + " rows, form " + std::to_string(form) + "]" : "");
    for (const auto &f : free)
      m.description += "; --free `" + shown(f) + "'";
    const std::vector<Setting> base{{"Sweeps/Drift temperatures", "40, 80, 120"}, {"Sweeps/Deviation angles", "0"}};
    surface_args(rng, c, m, "calibrate", usage ? std::vector<std::string>{} : std::vector<std::string>{measured}, base, hostile);
    for (const auto &f : free)
      m.args.insert(m.args.end(), {"--free", f});
    return m;
  }
} // namespace fuzz
