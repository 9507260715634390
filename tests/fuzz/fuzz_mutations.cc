// The mutation kinds: bad values, broken structure, a broken JSON form, odd command lines.
#include "fuzz_mutations.h"

#include "fuzz_surfaces.h"
#include "fuzz_values.h"

#include <algorithm>
#include <cstdint>

namespace fuzz
{
  namespace
  {
    /// `run INPUT -o out --set ...' in the usual order.
    std::vector<std::string> usual_args(const Context &c, const std::string &input)
    {
      std::vector<std::string> a{"run", input, "-o", "out"};
      for (const auto &s : c.fixed_sets)
        a.insert(a.end(), {"--set", s});
      return a;
    }

    Mutation value_mutation(Rng &rng, const Context &c)
    {
      Prm prm = c.prm;
      Mutation m;
      m.category = value_category;
      const int n = rng.coin() ? 1 : 2 + static_cast<int>(rng.below(2)); // one entry in half the runs
      for (int k = 0; k < n; ++k)
        {
          PrmLine &l = prm.lines[rng.pick(prm.entries)];
          const Replacement r = bad_value(rng, l.value, c.values);
          set_value(l, r.value);
          m.description += (k ? "; " : "") + ("`" + l.path + "' = " + r.label);
        }
      m.files["input.prm"] = prm.text();
      m.args = usual_args(c, "input.prm");
      return m;
    }

    /// Inserts `line' before line index `at' of the default file.
    std::string with_line(const Prm &prm, std::size_t at, const std::string &line)
    {
      Prm p = prm;
      PrmLine l;
      l.text = line;
      p.lines.insert(p.lines.begin() + std::min(at, p.lines.size()), l);
      return p.text();
    }

    std::string secret_file(Rng &rng, const std::string &marker)
    {
      const std::vector<std::string> first{marker, "token: " + marker, "export API_TOKEN=" + marker,
                                           "set Password = " + marker};
      return rng.pick(first) + "\nroot:" + marker + ":19000:0:99999:7:::\nThis is a private note, not a parameter file.\n";
    }

    Mutation structure_mutation(Rng &rng, const Context &c)
    {
      const Prm &prm = c.prm;
      Mutation m;
      m.category = structure_category;
      m.args = usual_args(c, "input.prm");
      std::string &text = m.files["input.prm"];
      const std::size_t n_lines = prm.lines.size();
      switch (rng.below(11))
        {
          case 0:
            {
              // mostly a line that means something: deleting one of the many comment lines proves little
              Prm p = prm;
              std::vector<std::size_t> meaningful;
              for (std::size_t k = 0; k < n_lines; ++k)
                if (prm.lines[k].kind != PrmLine::other)
                  meaningful.push_back(k);
              const std::size_t k = rng.below(4) ? rng.pick(meaningful) : rng.below(n_lines);
              m.description = "line " + std::to_string(k + 1) + " deleted: `" + shown(p.lines[k].text) + "'";
              p.lines.erase(p.lines.begin() + k);
              text = p.text();
              break;
            }
          case 1:
            {
              // duplicate a meaningful line (a comment twice proves nothing)
              const std::vector<std::size_t> &pool = rng.coin() ? prm.entries : prm.subsections;
              const std::size_t k = rng.pick(pool);
              m.description = "line " + std::to_string(k + 1) + " duplicated: `" + shown(prm.lines[k].text) + "'";
              text = with_line(prm, k + 1, prm.lines[k].text);
              break;
            }
          case 2:
            {
              Prm p = prm;
              const bool subsection = rng.coin();
              PrmLine &l = p.lines[rng.pick(subsection ? prm.subsections : prm.entries)];
              const std::string wrong = misspelled(rng, l.name);
              m.description = std::string(subsection ? "subsection" : "entry") + " name misspelled: `" + l.name +
                              "' -> `" + wrong + "'";
              if (subsection)
                l.text = l.indent + "subsection " + wrong;
              else
                l.text = l.indent + "set " + wrong + " = " + l.value;
              text = p.text();
              break;
            }
          case 3:
            {
              // a third level: one entry wrapped in a subsection of its own
              Prm p = prm;
              const std::size_t k = rng.pick(prm.entries);
              const std::vector<std::string> names{prm.lines[k].name, "Extra", prm.lines[rng.pick(prm.subsections)].name};
              const std::string name = rng.pick(names);
              m.description = "third level: `" + prm.lines[k].path + "' inside `subsection " + name + "'";
              PrmLine open, close;
              open.text = "  subsection " + name;
              close.text = "  end";
              p.lines.insert(p.lines.begin() + k + 1, close);
              p.lines.insert(p.lines.begin() + k, open);
              text = p.text();
              break;
            }
          case 4:
            {
              const std::size_t k = rng.below(n_lines + 1);
              m.description = "unbalanced `end' before line " + std::to_string(k + 1);
              text = with_line(prm, k, "end");
              break;
            }
          case 5:
            {
              const std::size_t k = rng.below(n_lines + 1);
              m.description = "`include input.prm' (itself) before line " + std::to_string(k + 1);
              text = with_line(prm, k, "include input.prm");
              break;
            }
          case 6:
            {
              const std::size_t k = rng.below(n_lines + 1);
              const std::string marker = secret_tag + std::to_string(rng.below(1000000000));
              m.files["secret.txt"] = secret_file(rng, marker);
              m.uses_secret = true;
              m.description = "`include secret.txt' (a private text file) before line " + std::to_string(k + 1);
              text = with_line(prm, k, "include secret.txt");
              break;
            }
          case 7:
            {
              const std::size_t k = rng.below(c.prm_text.size());
              m.description = "truncated at byte " + std::to_string(k) + " of " + std::to_string(c.prm_text.size());
              text = c.prm_text.substr(0, k);
              break;
            }
          case 8:
            {
              const std::size_t n = 1 + rng.below(4096);
              text = random_bytes(rng, n, true);
              m.description = "binary garbage of " + std::to_string(n) + " bytes";
              break;
            }
          case 9:
            {
              // garbage inside the file: the part before it is valid
              const std::size_t k = rng.below(n_lines + 1);
              const std::string g = rng.coin() ? high_bytes(rng, 1 + rng.below(80)) : random_bytes(rng, 1 + rng.below(80), false);
              m.description = "line of garbage `" + shown(g) + "' before line " + std::to_string(k + 1);
              text = with_line(prm, k, g);
              break;
            }
          default:
            {
              const bool json = rng.coin();
              m.files.clear();
              m.files[json ? "input.json" : "input.prm"] = "";
              m.args = usual_args(c, json ? "input.json" : "input.prm");
              m.description = std::string("an empty ") + (json ? ".json" : ".prm") + " file";
            }
        }
      return m;
    }

    Mutation json_mutation(Rng &rng, const Context &c)
    {
      Mutation m;
      m.category = json_category;
      m.args = usual_args(c, "input.json");
      std::string &text = m.files["input.json"];
      const std::string &json = c.json_text;
      switch (rng.below(5))
        {
          case 0:
          case 1:
            {
              const auto values = json_values(json);
              if (values.empty())
                {
                  text = json;
                  m.description = "JSON form unchanged (no \"value\" found to mutate)";
                  break;
                }
              const JsonValue &v = rng.pick(values);
              std::string replacement, label;
              if (rng.below(5) == 0) // a value of another JSON type
                {
                  const std::vector<std::string> types{"null", "true", "[1, 2]", "{\"x\": 1}", "1e999", "-0", "{}", "[]"};
                  replacement = label = rng.pick(types);
                }
              else
                {
                  const std::string original = json.substr(v.begin + 1, v.end - v.begin - 2);
                  const Replacement r = bad_value(rng, original, c.values);
                  replacement = json_string(r.value);
                  label = r.label;
                }
              text = json.substr(0, v.begin) + replacement + json.substr(v.end);
              m.description = "JSON `" + v.path + "' value = " + label;
              break;
            }
          case 2:
            {
              const std::vector<std::string> arrays{"[" + json + "]", "[]", "[1, \"a\", null]"};
              const std::size_t k = rng.below(arrays.size());
              text = arrays[k];
              m.description = std::string("JSON top-level array: ") + (k == 0 ? "[the JSON form]" : arrays[k]);
              break;
            }
          case 3:
            {
              const bool arrays = rng.coin();
              const int depth = 100000;
              std::string s;
              s.reserve(depth * 8);
              for (int k = 0; k < depth; ++k)
                s += arrays ? "[" : (k == 0 ? "{\"Pilot stage\": " : "{\"a\": ");
              s += "1";
              for (int k = 0; k < depth; ++k)
                s += arrays ? "]" : "}";
              text = s;
              m.description = std::string("JSON nested 100000 levels deep (") + (arrays ? "arrays" : "objects") + ")";
              break;
            }
          default:
            {
              const std::size_t k = rng.below(json.size());
              text = json.substr(0, k);
              m.description = "JSON truncated at byte " + std::to_string(k) + " of " + std::to_string(json.size());
            }
        }
      return m;
    }

    Mutation command_line_mutation(Rng &rng, const Context &c)
    {
      Mutation m;
      m.category = command_line_category;
      m.usage_allowed = true;
      m.files["input.prm"] = c.prm_text;
      m.args = usual_args(c, "input.prm");
      const PrmLine &e = c.prm.lines[rng.pick(c.prm.entries)];
      const std::string section = e.path.substr(0, e.path.rfind('/'));
      const auto add_set = [&](const std::string &s) { m.args.insert(m.args.end(), {"--set", s}); };
      switch (rng.below(9))
        {
          case 0:
            {
              const std::vector<std::string> garbage{
                "=",       "/=",   "=1",           "/Key=1",     section + "/=1", "//=//", section + "//" + e.name + "=1",
                " / = ",   "a=b=c", e.path + "==1", "--set",         "\"" + e.path + "\"=1"};
              std::string g = rng.coin() ? rng.pick(garbage) : random_bytes(rng, 1 + rng.below(64), false);
              if (g[0] == '-' && g != "--set") // random bytes must not turn into an option such as -o
                g[0] = 'x';
              add_set(g);
              m.description = "--set \"" + shown(g) + "\" (garbage)";
              break;
            }
          case 1:
            {
              const std::string s = rng.coin() ? e.path : e.path + " " + e.value;
              add_set(s);
              m.description = "--set \"" + shown(s) + "\" (no '=')";
              break;
            }
          case 2:
            {
              const std::vector<std::string> paths{e.path + "/x=1", section + "/Extra/" + e.name + "=" + e.value,
                                                   section + "/" + section + "/" + e.name + "=" + e.value};
              const std::string s = rng.pick(paths);
              add_set(s);
              m.description = "--set \"" + shown(s) + "\" (three-level path)";
              break;
            }
          case 3:
            {
              std::string v(50000, rng.coin() ? '7' : 'x');
              add_set(e.path + "=" + v);
              m.description = "--set \"" + e.path + "=<50000 x `" + v[0] + "'>\"";
              break;
            }
          case 4:
            {
              const std::string name = rng.coin() ? "valve.prm" : "valvedir";
              m.directory = name;
              m.args = usual_args(c, name);
              m.description = "input `" + name + "' is a directory";
              break;
            }
          case 5:
            {
              m.fifo = rng.coin() ? "valve.prm" : "valve.json";
              m.args = usual_args(c, m.fifo);
              m.description = "input `" + m.fifo + "' is a FIFO with no writer";
              break;
            }
          case 6:
            m.args = usual_args(c, "/dev/null");
            m.description = "input is /dev/null";
            break;
          case 7:
            {
              // the valve file after the options: README's usage allows it, so this must run
              m.args = {"run", "-o", "out"};
              for (const auto &s : c.fixed_sets)
                add_set(s);
              m.args.push_back("input.prm");
              m.expect_success = true;
              m.description = "valid valve file placed after the --set options";
              break;
            }
          default:
            {
              const std::vector<std::vector<std::string>> tails{{"--set"}, {"--frobnicate"}, {"-o"}, {"input.prm"}, {"--", "-o"}};
              const std::size_t k = rng.below(tails.size());
              for (const auto &t : tails[k])
                m.args.push_back(t);
              std::string joined;
              for (const auto &t : tails[k])
                joined += " " + t;
              m.description = "command line ending in" + joined;
            }
        }
      return m;
    }
  } // namespace

  Mutation mutation(Rng &rng, const Context &c, const std::array<bool, n_categories> &enabled)
  {
    // values and structure are where most bugs hide: weight them higher; with the first four kinds
    // alone the draw is the one before the surfaces were added, so old seeds replay
    const std::array<std::uint64_t, n_categories> weight{7, 5, 3, 5, 5, 5, 5};
    std::uint64_t total = 0;
    for (int k = 0; k < n_categories; ++k)
      total += enabled[k] ? weight[k] : 0;
    std::uint64_t r = rng.below(total);
    int kind = 0;
    for (; kind < n_categories - 1; ++kind)
      if (enabled[kind] && r < weight[kind])
        break;
      else if (enabled[kind])
        r -= weight[kind];
    switch (kind)
      {
        case value_category: return value_mutation(rng, c);
        case structure_category: return structure_mutation(rng, c);
        case json_category: return json_mutation(rng, c);
        case command_line_category: return command_line_mutation(rng, c);
        case tolerances_category: return tolerances_mutation(rng, c);
        case dynamics_category: return dynamics_mutation(rng, c);
        default: return calibrate_mutation(rng, c);
      }
  }
} // namespace fuzz
