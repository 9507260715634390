// The tolerance study's mutations: a few quantities toleranced validly, then hostile entries of
// `Tolerances' (ends of ranges, huge deviations, inconsistent distributions, hostile Correlations).
#include "fuzz_surfaces.h"

#include <algorithm>
#include <cstdio>

namespace fuzz
{
  namespace
  {
    /// A deviation as a short number (1e-06, not 9.9999999999999995e-07)
    std::string num(double x)
    {
      char b[32];
      std::snprintf(b, sizeof(b), "%.6g", x);
      return b;
    }

    std::string tol(const std::string &quantity, const std::string &key)
    {
      return "Tolerances/" + quantity + "/" + key;
    }

    /// The toleranced quantities the product declares: the subsections of `Tolerances' with a Distribution.
    std::vector<std::string> quantities(const Context &c)
    {
      std::vector<std::string> q;
      const std::string prefix = "Tolerances/", suffix = "/Distribution";
      for (auto k : c.prm.entries)
        {
          const std::string &p = c.prm.lines[k].path;
          if (p.rfind(prefix, 0) == 0 && p.size() > prefix.size() + suffix.size() &&
              p.compare(p.size() - suffix.size(), suffix.size(), suffix) == 0)
            q.push_back(p.substr(prefix.size(), p.size() - prefix.size() - suffix.size()));
        }
      return q;
    }

    /// A plausible deviation of a quantity in SI units (doc/user-guide.md section 5): um on bores, gaps
    /// and pole faces, 0.01 degree on the angles, 1 % on factors and remanences.
    double scale_of(const std::string &q)
    {
      if (q.find("discharge") != std::string::npos || q.find("remanence") != std::string::npos)
        return 0.01;
      if (q.find("angle") != std::string::npos || q == "Magnetic null")
        return 1.745e-4;
      return 1e-6;
    }

    /// A valid distribution of `q''s deviation: with these alone the study runs.
    void tolerance(Rng &rng, const std::string &q, std::vector<Setting> &s)
    {
      const std::string sc = num(scale_of(q)), two = num(2 * scale_of(q));
      switch (rng.below(3))
        {
          case 0: s.insert(s.end(), {{tol(q, "Distribution"), "normal"}, {tol(q, "Standard deviation"), sc}}); break;
          case 1:
            s.insert(s.end(), {{tol(q, "Distribution"), "truncated-normal"}, {tol(q, "Standard deviation"), sc},
                               {tol(q, "Lower bound"), "-" + two}, {tol(q, "Upper bound"), two}});
            break;
          default:
            s.insert(s.end(), {{tol(q, "Distribution"), "uniform"}, {tol(q, "Lower bound"), "-" + two}, {tol(q, "Upper bound"), two}});
        }
    }

    /// A hostile `Correlations' value over the toleranced a, b, c (u: not toleranced, may be empty).
    std::string correlations(Rng &rng, const std::string &a, const std::string &b, const std::string &cq, const std::string &u,
                             const std::vector<std::string> &all, std::string &label)
    {
      const std::string ab = a + " : " + b + " : ";
      switch (rng.below(11))
        {
          case 0: return label = "valid", ab + rng.pick(std::vector<std::string>{"0.5", "-0.5", "0.99"});
          case 1:
            return label = "rho at and beyond +-1, non-finite or no number",
                   ab + rng.pick(std::vector<std::string>{"1", "-1", "1.0000001", "-1.5", "0.9999999999999999", "nan", "inf",
                                                          "", "x", "1e-320", "1e308", "0.5 0.5", "0,5"});
          case 2:
            return label = "duplicate pair", rng.pick(std::vector<std::string>{ab + "0.5, " + ab + "0.5", ab + "0.5, " + ab + "0.3",
                                                                               ab + "0.5, " + b + " : " + a + " : 0.5",
                                                                               ab + "0.5, " + b + " : " + a + " : -0.5"});
          case 3: return label = "a quantity with itself", a + " : " + a + " : " + (rng.coin() ? "0.5" : "1");
          case 4:
            return label = "a quantity not toleranced or unknown",
                   rng.pick(std::vector<std::string>{a + " : " + (u.empty() ? "Unknown" : u) + " : 0.5", a + " : Unknown quantity : 0.5",
                                                     misspelled(rng, a) + " : " + b + " : 0.5", ab + "0.5, " + cq + " : Extra : 0.1"});
          case 5:
            return label = "empty items",
                   rng.pick(std::vector<std::string>{",,,", ",", " , , ", ab + "0.5,,,", "," + ab + "0.5", ab + "0.5,", " : : "});
          case 6:
            return label = "malformed item",
                   rng.pick(std::vector<std::string>{a + " : " + b, ab + "0.5 : 0.1", a + " " + b + " 0.5", ":::", a + " :: 0.5",
                                                     ": " + b + " : 0.5", a + ":" + b + ":0.5", a + " ; " + b + " ; 0.5"});
          case 7:
            return label = "not positive definite", ab + "0.9, " + b + " : " + cq + " : 0.9, " + a + " : " + cq + " : -0.9";
          case 8:
            {
              // every pair of every quantity: 0.3 is positive definite, -0.1 is not, 0.999999 nearly singular
              const std::string rho = rng.pick(std::vector<std::string>{"0.3", "-0.1", "0.999999"});
              std::string s;
              for (std::size_t i = 0; i < all.size(); ++i)
                for (std::size_t j = i + 1; j < all.size(); ++j)
                  s += (s.empty() ? "" : ", ") + all[i] + " : " + all[j] + " : " + rho;
              return label = "every pair at " + rho, s;
            }
          case 9:
            {
              std::string s;
              for (int k = 0; k < 2000; ++k) // about 100 kB: still one command-line argument
                s += (k ? ", " : "") + ab + "0.1";
              return label = "the same pair 2000 times", s;
            }
          default:
            {
              const std::string g = rng.coin() ? high_bytes(rng, 1 + rng.below(40)) : random_bytes(rng, 1 + rng.below(40), false);
              return label = "bytes", rng.coin() ? g : ab + g;
            }
        }
    }
  } // namespace

  Mutation tolerances_mutation(Rng &rng, const Context &c)
  {
    Mutation m;
    m.category = tolerances_category;
    m.tables = true;
    const std::vector<std::string> all = quantities(c);
    // a study of about a second: three drift temperatures, a few dozen valves, Sobol' now and then
    std::vector<Setting> base{{"Sweeps/Drift temperatures", "40, 80, 120"},
                              // now and then a single valve or two: statistics of one value
                              {"Tolerances/Samples", std::to_string(rng.below(6) ? 8 + rng.below(40) : 1 + rng.below(2))},
                              {"Tolerances/Sobol base samples", rng.below(3) ? "0" : "64"},
                              {"Tolerances/Bootstrap size", "20"},
                              {"Tolerances/Sampling", rng.pick(std::vector<std::string>{"monte-carlo", "latin-hypercube",
                                                                                        "randomised-sobol-sequence"})}};
    std::vector<std::string> chosen = all, rest;
    for (std::size_t k = chosen.size(); k > 1; --k) // a seeded shuffle (std::shuffle is implementation-defined)
      std::swap(chosen[k - 1], chosen[rng.below(k)]);
    if (chosen.size() < 3)
      {
        m.description = "the study alone (fewer than 3 toleranced quantities declared)";
        surface_args(rng, c, m, "tolerances", {}, base, {});
        return m;
      }
    const std::size_t n_chosen = rng.below(8) == 0 ? chosen.size() : 3 + rng.below(2); // >= 3: Correlations needs them
    rest.assign(chosen.begin() + n_chosen, chosen.end());
    chosen.resize(n_chosen);
    for (const auto &q : chosen)
      tolerance(rng, q, base);
    m.description = std::to_string(n_chosen) + " quantities toleranced; ";

    std::vector<Setting> hostile;
    std::vector<std::string> labels;
    const auto set = [&](const std::string &path, const std::string &value, const std::string &why) {
      hostile.push_back({path, value});
      labels.push_back("`" + path + "' = `" + shown(value) + "'" + (why.empty() ? "" : " (" + why + ")"));
    };
    // mostly one hostile entry: a second one's range check would often hide the first one's effect
    const int n = rng.below(3) ? 1 : 2;
    for (int k = 0; k < n; ++k)
      {
        const std::string &q = rng.pick(chosen);
        switch (rng.below(11))
          {
            case 9: labels.push_back("broken table " + broken_table(rng, c, m)); break;
            case 10:
              {
                std::string label;
                hostile.push_back(valve_range_setting(rng, c, label));
                labels.push_back(label);
                break;
              }
            case 0:
              {
                std::string label;
                hostile.push_back(range_setting(rng, c, tol(q, rng.pick(std::vector<std::string>{"Mean", "Standard deviation",
                                                                                              "Lower bound", "Upper bound"})),
                                                label));
                labels.push_back(label);
                break;
              }
            case 1:
              {
                // a huge deviation: 1 rad on an angle is a valve far off its table; 1 m on a bore is no valve
                const auto angle = std::find(all.begin(), all.end(), "Magnetic null");
                const std::string h = rng.coin() && angle != all.end() ? *angle : rng.pick(all);
                const bool truncated = rng.coin();
                set(tol(h, "Distribution"), truncated ? "truncated-normal" : "normal", "");
                set(tol(h, "Standard deviation"), rng.pick(std::vector<std::string>{"1", "0.1", "0.01"}), "huge");
                if (truncated)
                  set(tol(h, "Lower bound"), "-1", ""), set(tol(h, "Upper bound"), "1", "");
                break;
              }
            case 2:
              {
                // distributions that contradict themselves or hold (almost) no valve
                const std::string sc = num(scale_of(q));
                switch (rng.below(6))
                  {
                    case 0: set(tol(q, "Lower bound"), sc, "bounds exclude 0"), set(tol(q, "Upper bound"), num(2 * scale_of(q)), ""); break;
                    case 1: set(tol(q, "Lower bound"), sc, "lower above upper"), set(tol(q, "Upper bound"), "-" + sc, ""); break;
                    case 2: set(tol(q, "Lower bound"), "0", "no width"), set(tol(q, "Upper bound"), "0", ""); break;
                    case 3:
                      set(tol(q, "Distribution"), rng.coin() ? "normal" : "truncated-normal", "");
                      set(tol(q, "Standard deviation"), rng.pick(std::vector<std::string>{"0", "-0", "1e-300", "4.9406564584124654e-324"}),
                          "no spread");
                      break;
                    case 4:
                      set(tol(q, "Distribution"), "truncated-normal", "");
                      set(tol(q, "Mean"), rng.coin() ? "1" : "-1", "mean far outside the bounds");
                      set(tol(q, "Standard deviation"), sc, ""), set(tol(q, "Lower bound"), "-" + sc, ""), set(tol(q, "Upper bound"), sc, "");
                      break;
                    default:
                      set(tol(q, "Lower bound"), "-1e-300", "width 2e-300"), set(tol(q, "Upper bound"), "1e-300", "");
                  }
                break;
              }
            case 3:
            case 4:
              {
                std::string label;
                const std::string v = correlations(rng, chosen[0], chosen[1], chosen[2], rest.empty() ? "" : rng.pick(rest), all, label);
                if (label.rfind("every pair", 0) == 0)
                  for (const auto &a : rest) // every quantity toleranced, or the matrix names untoleranced ones
                    tolerance(rng, a, base);
                set("Tolerances/Correlations", v, label);
                if (rng.below(4) == 0)
                  set("Tolerances/Sobol base samples", "64", "Sobol' with a copula");
                break;
              }
            case 5:
              {
                // the study's own entries at and beyond their ends, and just under Sobol''s floor of 64
                const std::vector<std::string> study{"Tolerances/Samples",         "Tolerances/Sobol base samples",
                                                     "Tolerances/Null-shift spec", "Tolerances/Bootstrap size",
                                                     "Tolerances/Confidence level", "Tolerances/Seed"};
                if (rng.below(4) == 0)
                  set(rng.coin() ? "Tolerances/Sobol base samples" : "Tolerances/Null-shift spec",
                      rng.pick(std::vector<std::string>{"63", "1", "1e-300", "-0"}), "");
                else
                  {
                    std::string label;
                    hostile.push_back(range_setting(rng, c, rng.pick(study), label));
                    labels.push_back(label);
                  }
                break;
              }
            case 6:
              {
                // selections misspelled, in another case, empty, or a distribution's neighbour value
                const std::vector<std::string> keys{tol(q, "Distribution"), "Tolerances/Sampling", "Tolerances/Sobol estimator"};
                const std::string key = rng.pick(keys);
                const std::vector<std::string> values{"Normal", "", "normal ", "truncated normal", "gaussian", "none, normal",
                                                      misspelled(rng, "uniform"), "latin-hypercube", "martinez"};
                set(key, rng.pick(values), "selection");
                break;
              }
            case 7:
              {
                // the valve itself off nominal at the ends of Asymmetry or Offsets, then toleranced around it
                std::vector<std::string> entries = ranged_entries(c, "Asymmetry/"), offsets = ranged_entries(c, "Offsets/");
                entries.insert(entries.end(), offsets.begin(), offsets.end());
                if (entries.empty())
                  break;
                std::string label;
                hostile.push_back(range_setting(rng, c, rng.pick(entries), label));
                labels.push_back(label);
                break;
              }
            default:
              bad_entry_under(rng, c, {"Tolerances/"}, hostile, labels); // bytes, non-finite, huge lists
          }
      }
    for (std::size_t k = 0; k < labels.size(); ++k)
      m.description += (k ? "; " : "") + labels[k];
    surface_args(rng, c, m, "tolerances", {}, base, hostile);
    return m;
  }
} // namespace fuzz
