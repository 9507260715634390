#include "common/parameter_messages.h"

#include "common/error.h"
#include "common/parameter_input.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace servodrift
{
  using dealii::ParameterHandler;
  using boost::property_tree::ptree;

  std::string collapse_whitespace(const std::string &text)
  {
    std::string out;
    bool space = false;
    for (char c : text)
      if (std::isspace(static_cast<unsigned char>(c)))
        space = !out.empty();
      else
        {
          if (space)
            out += ' ';
          out += c;
          space = false;
        }
    return out;
  }

  std::string shown_input(const std::string &text, std::size_t limit)
  {
    std::string out;
    for (char c : collapse_whitespace(text.substr(0, 4 * limit)))
      out += (static_cast<unsigned char>(c) >= 0x20 && static_cast<unsigned char>(c) < 0x7f) ? c : '?';
    if (out.size() > limit || text.size() > 4 * limit)
      out = out.substr(0, limit) + "... (" + std::to_string(text.size()) + " characters)";
    return out;
  }

  namespace
  {
    std::size_t edit_distance(const std::string &a, const std::string &b)
    {
      std::vector<std::size_t> row(b.size() + 1);
      for (std::size_t j = 0; j <= b.size(); ++j)
        row[j] = j;
      for (std::size_t i = 1; i <= a.size(); ++i)
        {
          std::size_t diagonal = row[0];
          row[0] = i;
          for (std::size_t j = 1; j <= b.size(); ++j)
            {
              const std::size_t up = row[j];
              const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                                std::tolower(static_cast<unsigned char>(b[j - 1]));
              row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
              diagonal = up;
            }
        }
      return row[b.size()];
    }

    /// Every declaration with its value, pattern and documentation, as deal.II prints it in JSON.
    ptree declarations(const ParameterHandler &prm)
    {
      std::ostringstream json;
      prm.print_parameters(json, ParameterHandler::JSON);
      std::istringstream in(json.str());
      ptree tree;
      boost::property_tree::read_json(in, tree);
      return tree;
    }
    /// Every number of every Double entry converts to a finite, normal double: deal.II's pattern
    /// accepts a subnormal such as 1e-310, its conversion then fails with a raw exception.
    void check_numbers(const ptree &node, const std::string &path)
    {
      for (const auto &[name, child] : node)
        {
          const std::string entry = path.empty() ? name : path + "/" + name;
          const auto value = child.get_child_optional("value");
          if (!value)
            {
              check_numbers(child, entry);
              continue;
            }
          const std::string pattern = child.get<std::string>("pattern_description", "");
          if (pattern.rfind("[Double", 0) != 0 && pattern.rfind("[List of <[Double", 0) != 0)
            continue;
          std::istringstream items(value->data());
          for (std::string item; std::getline(items, item, ',');)
            {
              if (collapse_whitespace(item).empty())
                continue;
              errno = 0;
              const double x = std::strtod(item.c_str(), nullptr);
              if (errno == ERANGE || !std::isfinite(x) || (x != 0 && !std::isnormal(x)))
                throw InputError("`" + entry + "' = " + shown_input(value->data()) + ": " +
                                 shown_input(collapse_whitespace(item)) +
                                 " is not a usable number (a double lies within +-2.2e-308 ... +-1.8e308, or is 0); "
                                 "allowed: " + pattern);
            }
        }
    }
  } // namespace

  /// The declared names under a subsection path: its subsections or its entries.
  std::vector<std::string> declared_names(const ParameterHandler &prm, const std::vector<std::string> &path,
                                          bool subsections)
  {
    const ptree tree = declarations(prm);
    const ptree *node = &tree;
    for (const auto &p : path)
      {
        const auto child = node->get_child_optional(ptree::path_type(p, '\0'));
        if (!child)
          return {};
        node = &*child;
      }
    std::vector<std::string> names;
    for (const auto &child : *node)
      if (bool(child.second.get_child_optional("value")) != subsections)
        names.push_back(child.first);
    return names;
  }

  /// " (did you mean `X'?)" for the nearest declared name, if it is near enough to be a typo.
  std::string suggestion(const std::string &given, const std::vector<std::string> &names)
  {
    if (given.size() > 200)
      return "";
    std::string best;
    std::size_t best_distance = std::max<std::size_t>(2, given.size() / 3) + 1;
    for (const auto &n : names)
      if (const std::size_t d = edit_distance(given, n); d < best_distance)
        best = n, best_distance = d;
    return best.empty() ? "" : " (did you mean `" + best + "'?)";
  }

  std::string joined(const std::vector<std::string> &path)
  {
    std::string s;
    for (const auto &p : path)
      s += (s.empty() ? "" : "/") + p;
    return s;
  }

  void check_numbers(const ParameterHandler &prm)
  {
    check_numbers(declarations(prm), "");
  }

  std::string exception_text(const dealii::ExceptionBase &e)
  {
    std::ostringstream s;
    e.print_info(s);
    return collapse_whitespace(s.str());
  }

  std::optional<std::string> mismatched_pattern(const dealii::ExceptionBase &e)
  {
    const std::string info = exception_text(e), mark = "> does not match the given pattern <";
    const auto p = info.rfind(mark);
    if (p == std::string::npos || info.size() < p + mark.size() + 2)
      return std::nullopt;
    return info.substr(p + mark.size(), info.size() - p - mark.size() - 2); // without the closing ">."
  }
} // namespace servodrift
