#include "common/moved_entries.h"

#include "common/error.h"
#include "common/parameter_input.h"
#include "common/parameter_messages.h"
#include "common/parameters/renamed_entries.h"
#include "common/sweep.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <iostream>
#include <mutex>
#include <optional>
#include <sstream>

namespace servodrift
{
  using dealii::ParameterHandler;

  namespace
  {
    /// Sets `value' at `path' ("A/B/Key", from the handler's top level). Returns the allowed
    /// pattern if deal.II refuses the value.
    std::optional<std::string> set_at_path(ParameterHandler &prm, const std::string &path, const std::string &value)
    {
      std::vector<std::string> sections;
      std::string key = path;
      for (std::size_t slash; (slash = key.find('/')) != std::string::npos; key = key.substr(slash + 1))
        sections.push_back(key.substr(0, slash));
      for (const auto &section : sections)
        prm.enter_subsection(section);
      std::optional<std::string> refused;
      try
        {
          prm.set(key, value);
        }
      catch (const dealii::ExceptionBase &e)
        {
          refused = mismatched_pattern(e).value_or("see `servodrift params'");
        }
      for (std::size_t k = 0; k < sections.size(); ++k)
        prm.leave_subsection();
      return refused;
    }
  } // namespace

  void warn_once(const std::string &line)
  {
    static std::mutex mutex;
    static std::set<std::string> printed;
    const std::lock_guard<std::mutex> lock(mutex);
    if (mpi_rank() == 0 && printed.insert(line).second)
      std::cerr << line << std::endl;
  }

  bool MovedEntries::take(const std::string &path, const std::string &value, const std::string &where)
  {
    if (const RetiredEntry *gone = retired_entry(path))
      {
        retired.push_back(retirement_warning(where, *gone));
        return true;
      }
    const RenamedEntry *entry = renamed_entry(path);
    if (entry == nullptr)
      {
        set_paths.insert(path);
        return false;
      }
    values.push_back({entry, value, where});
    return true;
  }

  void MovedEntries::apply(ParameterHandler &prm) const
  {
    for (const auto &[entry, value, where] : values)
      {
        if (set_paths.count(entry->new_path) != 0)
          throw InputError(where + ": `" + entry->old_path + "' is the old name of `" + entry->new_path +
                           "', which the file sets too; keep one");
        if (const auto pattern = set_at_path(prm, entry->new_path, value))
          throw InputError(where + ": `" + entry->old_path + "' (now `" + entry->new_path + "') = " +
                           shown_input(value) + " is not allowed; allowed: " + *pattern);
        warn_once(deprecation_warning(where, *entry));
      }
    for (const auto &warning : retired)
      warn_once(warning);
  }

  std::string without_moved_entries(const std::string &text, const std::string &file, MovedEntries &moved)
  {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
      lines.push_back(line);
    std::vector<std::string> path;
    for (std::size_t k = 0; k < lines.size();)
      {
        const std::size_t first = k;
        std::string logical; // a line and the lines its trailing backslashes continue it with
        for (bool continued = true; continued && k < lines.size(); ++k)
          {
            std::string line = lines[k];
            const auto last = line.find_last_not_of(" \t\r");
            continued = last != std::string::npos && line[last] == '\\';
            logical += continued ? line.substr(0, last) : line;
          }
        const std::string statement = collapse_whitespace(logical.substr(0, logical.find('#')));
        if (statement.rfind("subsection ", 0) == 0)
          path.push_back(statement.substr(11));
        else if (statement == "end" && !path.empty())
          path.pop_back();
        else if (statement.rfind("set ", 0) == 0 && statement.find('=') != std::string::npos)
          {
            const auto eq = statement.find('=');
            const std::string key = collapse_whitespace(statement.substr(4, eq - 4));
            const std::string value = collapse_whitespace(statement.substr(eq + 1));
            const std::string where = file + ":" + std::to_string(first + 1);
            if (moved.take(joined(path) + "/" + key, value, where))
              for (std::size_t j = first; j < k; ++j)
                lines[j].clear();
          }
      }
    std::string out;
    for (const auto &line : lines)
      out += line + "\n";
    return out;
  }

  std::string current_entry_path(const std::string &path, const std::string &where)
  {
    if (const RetiredEntry *gone = retired_entry(path))
      throw InputError(where + ": `" + gone->path + "' is no longer read (" + gone->why + ")");
    const RenamedEntry *moved = renamed_entry(path);
    if (moved == nullptr)
      return path;
    warn_once(deprecation_warning(where, *moved));
    return moved->new_path;
  }
} // namespace servodrift
