// Mutated values: how a bad value for an entry, random bytes and a misspelled name are drawn.
#include "fuzz_values.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <utility>

namespace fuzz
{
  namespace
  {
    /// Every number of `value' (a scalar, a list, `T angle current' triples) multiplied by `factor';
    /// words stay as they are. `found' says whether there was any number to scale.
    std::string scaled(const std::string &value, double factor, bool &found)
    {
      found = false;
      std::string out;
      for (std::size_t k = 0; k < value.size();)
        {
          const char c = value[k];
          const bool after_word = k > 0 && (std::isalnum(static_cast<unsigned char>(value[k - 1])) || value[k - 1] == '_');
          const bool may_start = std::isdigit(static_cast<unsigned char>(c)) ||
                                 ((c == '-' || c == '+' || c == '.') && k + 1 < value.size() &&
                                  (std::isdigit(static_cast<unsigned char>(value[k + 1])) || value[k + 1] == '.'));
          if (may_start && !after_word)
            {
              char *end = nullptr;
              const double x = std::strtod(value.c_str() + k, &end);
              const std::size_t n = end - (value.c_str() + k);
              if (n > 0)
                {
                  out += format_double(x * factor);
                  k += n;
                  found = true;
                  continue;
                }
            }
          out += c;
          ++k;
        }
      return out;
    }
  } // namespace

  std::string random_bytes(Rng &rng, std::size_t n, bool allow_nul)
  {
    std::string s;
    for (std::size_t k = 0; k < n; ++k)
      {
        unsigned char c = static_cast<unsigned char>(rng.below(256));
        if (c == 0 && !allow_nul)
          c = 0x01;
        s += static_cast<char>(c);
      }
    return s;
  }

  std::string high_bytes(Rng &rng, std::size_t n)
  {
    std::string s;
    for (std::size_t k = 0; k < n; ++k)
      s += static_cast<char>(rng.coin() ? 0x80 + rng.below(128) : 0x20 + rng.below(95));
    return s;
  }

  Replacement bad_value(Rng &rng, const std::string &original, const std::vector<std::string> &other_values)
  {
    // scaled values count twice: they are the ones that get past the checks into the physics
    std::uint64_t choice = rng.below(13);
    if (choice >= 11)
      choice = 3;
    switch (choice)
      {
        case 0:
          return {"0", "0"};
        case 1:
          return {"-1", "-1"};
        case 2:
          return {"1", "1"};
        case 3:
          {
            const std::vector<double> factors{-1, 0.001, 0.1, 0.5, 2, 10, 1000};
            const double f = rng.pick(factors);
            bool found = false;
            const std::string v = scaled(original, f, found);
            if (found)
              return {v, "value x " + format_double(f) + " = " + shown(v)};
            return {format_double(f), format_double(f) + " (value not numeric)"};
          }
        case 4:
          {
            const std::vector<std::string> extremes{"1e308", "-1e308", "1e309", "1e-310", "1e-300",
                                                    "nan",   "-nan",   "inf",   "-inf",   "Infinity"};
            const std::string v = rng.pick(extremes);
            if (rng.coin())
              return {v, v};
            // inside a list too: the first element replaced
            bool found = false;
            std::string list = original;
            const auto comma = list.find(',');
            if (comma != std::string::npos)
              {
                list = v + list.substr(comma);
                found = true;
              }
            return found ? Replacement{list, shown(list)} : Replacement{v, v};
          }
        case 5:
          return {"", "empty value"};
        case 6:
          {
            const std::vector<std::string> fill{"a", "9", "1e-3, ", " "};
            const std::string &unit = rng.pick(fill);
            std::string v;
            while (v.size() < 50000)
              v += unit;
            v.resize(50000);
            return {v, "50000 characters of `" + unit + "'"};
          }
        case 7:
          {
            const bool high = rng.coin(); // half the time no control characters, to get past a text check
            const std::string v = high ? high_bytes(rng, 1 + rng.below(64)) : random_bytes(rng, 1 + rng.below(64), true);
            return {v, std::string(high ? "non-UTF-8 bytes `" : "random bytes `") + shown(v) + "'"};
          }
        case 8:
          {
            std::string v;
            const bool sequence = rng.coin();
            for (int k = 0; k < 10000; ++k)
              v += (k ? ", " : "") + (sequence ? std::to_string(k) : format_double(std::ldexp(double(rng.below(1u << 20)), -10)));
            return {v, std::string("a list of 10000 ") + (sequence ? "integers 0..9999" : "random numbers")};
          }
        case 9:
          {
            const std::string &v = rng.pick(other_values);
            return {v, "another entry's value `" + shown(v) + "'"};
          }
        default:
          {
            // a value with a trailing word or two numbers where one is wanted
            const std::vector<std::string> odd{original + " m", original + " " + original, original + ",",
                                               "," + original, "1e", "0x10", "--1", "1,5"};
            const std::string v = rng.pick(odd);
            return {v, "malformed `" + shown(v) + "'"};
          }
      }
  }

  std::string misspelled(Rng &rng, std::string name)
  {
    if (name.empty())
      return "x";
    const std::size_t k = rng.below(name.size());
    switch (rng.below(4))
      {
        case 0:
          name.erase(k, 1);
          break;
        case 1:
          name.insert(k, 1, static_cast<char>('a' + rng.below(26)));
          break;
        case 2:
          name[k] = std::isupper(static_cast<unsigned char>(name[k])) ? std::tolower(name[k]) : std::toupper(name[k]);
          break;
        default:
          if (k + 1 < name.size())
            std::swap(name[k], name[k + 1]);
          else
            name += 's';
      }
    return name;
  }
} // namespace fuzz
