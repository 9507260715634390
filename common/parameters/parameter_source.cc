#include "common/parameters/parameter_source.h"

#include "common/error.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace servodrift
{
  std::string parameters::trimmed(const std::string &text)
  {
    const auto first = text.find_first_not_of(" \t\r\n");
    if (first == std::string::npos)
      return "";
    return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
  }

  std::vector<std::string> parameters::split_list(const std::string &text, char separator)
  {
    std::string rest = text;
    while (!rest.empty() && rest.back() == ' ')
      rest.pop_back();
    std::vector<std::string> items;
    while (!rest.empty())
      {
        const auto at = rest.find(separator);
        const std::string item = trimmed(rest.substr(0, at));
        rest = at == std::string::npos ? "" : rest.substr(at + 1);
        if (separator != ' ' || !item.empty())
          items.push_back(item);
      }
    return items;
  }

  namespace
  {
    using parameters::split_list;
    using parameters::trimmed;

    std::string joined(const std::vector<std::string> &parts, const std::string &last)
    {
      std::string path;
      for (const auto &p : parts)
        path += p + "/";
      return path + last;
    }

    bool to_double(const std::string &text, double &value)
    {
      const std::string t = trimmed(text);
      if (t.empty())
        return false;
      char *end = nullptr;
      errno = 0;
      value = std::strtod(t.c_str(), &end);
      return end == t.c_str() + t.size() && errno != ERANGE && std::isfinite(value);
    }

    bool to_long(const std::string &text, long &value)
    {
      const std::string t = trimmed(text);
      if (t.empty())
        return false;
      char *end = nullptr;
      errno = 0;
      value = std::strtol(t.c_str(), &end, 10);
      return end == t.c_str() + t.size() && errno != ERANGE;
    }
  } // namespace

  double ParameterSource::get_double(const std::string &key) const
  {
    double value;
    if (!to_double(get(key), value))
      throw InputError(origin() + "entry `" + path_of(key) + "' = `" + get(key) + "' is not a finite number");
    return value;
  }

  long ParameterSource::get_integer(const std::string &key) const
  {
    long value;
    if (!to_long(get(key), value))
      throw InputError(origin() + "entry `" + path_of(key) + "' = `" + get(key) + "' is not an integer");
    return value;
  }

  bool ParameterSource::get_bool(const std::string &key) const
  {
    const std::string t = trimmed(get(key));
    if (t == "true" || t == "yes")
      return true;
    if (t == "false" || t == "no")
      return false;
    throw InputError(origin() + "entry `" + path_of(key) + "' = `" + t + "' is not true or false");
  }

  std::vector<double> ParameterSource::get_double_list(const std::string &key) const
  {
    std::vector<double> values;
    for (const auto &item : split_list(get(key)))
      {
        double value;
        if (!to_double(item, value))
          throw InputError(origin() + "entry `" + path_of(key) + "': `" + item + "' is not a finite number");
        values.push_back(value);
      }
    return values;
  }

  std::vector<int> ParameterSource::get_integer_list(const std::string &key) const
  {
    std::vector<int> values;
    for (const auto &item : split_list(get(key)))
      {
        long value;
        if (!to_long(item, value) || value != static_cast<int>(value))
          throw InputError(origin() + "entry `" + path_of(key) + "': `" + item + "' is not an integer");
        values.push_back(static_cast<int>(value));
      }
    return values;
  }

  PrmText::PrmText(const std::string &text, const std::string &name_)
    : name(name_)
  {
    std::istringstream in(text);
    std::string raw, line;
    std::vector<std::string> open;
    int number = 0, first_of_line = 0;
    while (std::getline(in, raw))
      {
        ++number;
        if (line.empty())
          first_of_line = number;
        const auto hash = raw.find('#');
        std::string part = trimmed(hash == std::string::npos ? raw : raw.substr(0, hash));
        if (!part.empty() && part.back() == '\\')
          {
            line += part.substr(0, part.size() - 1) + " ";
            continue;
          }
        line = trimmed(line + part);
        const std::string where = name + ":" + std::to_string(first_of_line) + ": ";
        if (line.empty())
          ;
        else if (line.rfind("subsection ", 0) == 0)
          open.push_back(trimmed(line.substr(11)));
        else if (line == "end")
          {
            if (open.empty())
              throw InputError(where + "`end' without a subsection");
            open.pop_back();
          }
        else if (line.rfind("set ", 0) == 0 && line.find('=') != std::string::npos)
          {
            const auto equals = line.find('=');
            values[joined(open, trimmed(line.substr(4, equals - 4)))] = trimmed(line.substr(equals + 1));
          }
        else
          throw InputError(where + "`" + line.substr(0, 60) + "' is not `subsection', `set Key = value' or `end'");
        line.clear();
      }
    if (!open.empty())
      throw InputError(name + ": subsection `" + joined(open, "") + "' has no `end'");
  }

  void PrmText::enter_subsection(const std::string &subsection)
  {
    current.push_back(subsection);
  }

  void PrmText::leave_subsection()
  {
    if (!current.empty())
      current.pop_back();
  }

  std::string PrmText::get(const std::string &key) const
  {
    const auto it = values.find(joined(current, key));
    if (it == values.end())
      throw InputError(name + ": entry `" + path_of(key) + "' is missing");
    return it->second;
  }

  std::string PrmText::path_of(const std::string &key) const
  {
    return joined(current, key);
  }
} // namespace servodrift
