#include "common/parameter_input.h"

#include "common/output_files.h"

#include "common/error.h"
#include "common/parameter_messages.h"
#include "common/moved_entries.h"
#include "common/parameters/renamed_entries.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

namespace servodrift
{
  using dealii::ParameterHandler;
  using boost::property_tree::ptree;

  namespace
  {
    const std::string list_hint = " (`servodrift params' lists every entry)";

    /// The text between `open' and the next `close' after `from' (npos if absent).
    std::optional<std::string> between(const std::string &s, const std::string &open, const std::string &close,
                                       std::size_t from = 0)
    {
      const auto a = s.find(open, from);
      if (a == std::string::npos)
        return std::nullopt;
      const auto b = s.find(close, a + open.size());
      if (b == std::string::npos)
        return std::nullopt;
      return s.substr(a + open.size(), b - a - open.size());
    }

    // ---- files ------------------------------------------------------------------------------------
    /// The content of a parameter file (the input or one it includes): a text file of a few kB.
    std::string text_file(const std::string &file, const std::string &what)
    {
      return read_text_file(file, what, input_limits::file_bytes);
    }

    /// The subsection path ("A/B/") open at a given line of a PRM text.
    std::string subsection_at_line(const std::string &text, int line_number)
    {
      std::istringstream in(text);
      std::vector<std::string> path;
      std::string line;
      for (int k = 1; k < line_number && std::getline(in, line); ++k)
        {
          line = collapse_whitespace(line.substr(0, line.find('#')));
          if (line.rfind("subsection ", 0) == 0)
            path.push_back(line.substr(11));
          else if (line == "end" && !path.empty())
            path.pop_back();
        }
      return path.empty() ? "" : joined(path) + "/";
    }

    /// Follows the `include' lines of a PRM file as deal.II will (relative to the working
    /// directory), refusing a cycle, a depth beyond input_limits::include_depth and anything that
    /// is not a text file, before deal.II follows them without a bound.
    void check_includes(const std::string &file, std::vector<std::string> &chain)
    {
      const std::string text = text_file(file, chain.empty() ? "a parameter file" : "a parameter file to include");
      chain.push_back(file);
      std::istringstream in(text);
      std::string line;
      for (int number = 1; std::getline(in, line); ++number)
        {
          line = collapse_whitespace(line.substr(0, line.find('#')));
          if (line.rfind("include ", 0) != 0 && line.rfind("INCLUDE ", 0) != 0)
            continue;
          const std::string included = line.substr(8);
          const std::string where = file + ":" + std::to_string(number) + ": include " + shown_input(included);
          namespace fs = std::filesystem;
          std::error_code ec, ec_f;
          const auto canonical = fs::weakly_canonical(included, ec);
          for (const auto &f : chain)
            if (!ec && fs::weakly_canonical(f, ec_f) == canonical)
              throw InputError(where + ": the file includes itself (through " + std::to_string(chain.size()) +
                               " file(s)); remove the include");
          if (static_cast<int>(chain.size()) > input_limits::include_depth)
            throw InputError(where + ": includes nest deeper than " + std::to_string(input_limits::include_depth) +
                             " files");
          check_includes(included, chain);
        }
      chain.pop_back();
    }

    /// Turns a deal.II parse error of a PRM file into one line naming file, line, entry and range.
    std::string describe_parse_error(const std::string &file, const std::string &text, const ParameterHandler &prm,
                                     const dealii::ExceptionBase &e)
    {
      const std::string info = exception_text(e);
      // "Line <N> of file <F>: ..." (ExcNoSubsection omits the '>')
      const auto number = between(info, "Line <", ">");
      const auto file_start = info.find("of file <");
      if (!number || file_start == std::string::npos)
        return file + ": " + shown_input(info, 200);
      const auto file_end = std::min(info.find(">:", file_start), info.find(": ", file_start));
      if (file_end == std::string::npos)
        return file + ": " + shown_input(info, 200);
      const std::string in_file = info.substr(file_start + 9, file_end - file_start - 9);
      const std::string rest = info.substr(info.find(": ", file_end) == std::string::npos ? info.size() :
                                                                                           info.find(": ", file_end) + 2);
      const int line = std::atoi(number->c_str());
      const std::string at = in_file + ":" + *number + ": ";
      std::string section;
      try
        {
          section = subsection_at_line(in_file == file ? text : text_file(in_file, "a parameter file to include"), line);
        }
      catch (const InputError &)
        {
          // an included file that cannot be read again: the message names no subsection
        }

      const std::string value_mark = "The entry value ", name_mark = " for the entry named ",
                        pattern_mark = " does not match the given pattern: ";
      if (rest.rfind(value_mark, 0) == 0)
        {
          const auto p = rest.rfind(pattern_mark), n = rest.rfind(name_mark, p);
          if (p != std::string::npos && n != std::string::npos && n >= value_mark.size())
            return at + "`" + section + rest.substr(n + name_mark.size(), p - n - name_mark.size()) + "' = " +
                   shown_input(rest.substr(value_mark.size(), n - value_mark.size())) +
                   " is not allowed; allowed: " + rest.substr(p + pattern_mark.size());
        }
      const std::string where = section.empty() ? std::string(" (at top level)") :
                                                  " (in subsection `" + section.substr(0, section.size() - 1) + "')";
      if (const auto entry = between(rest, "No entry with name <", "> was declared"))
        {
          std::vector<std::string> path;
          for (std::string s = section; !s.empty(); s = s.substr(s.find('/') + 1))
            path.push_back(s.substr(0, s.find('/')));
          if (const RenamedEntry *moved = renamed_entry(section + *entry))
            return at + "`" + moved->old_path + "' is now `" + moved->new_path +
                   "' (an included file is read as written: rename it there)";
          if (const RetiredEntry *gone = retired_entry(section + *entry))
            return at + "`" + gone->path + "' is no longer read (" + gone->why +
                   "; an included file is read as written: remove it there)";
          return at + "no entry `" + shown_input(*entry) + "'" + where +
                 suggestion(*entry, declared_names(prm, path, false)) + list_hint;
        }
      if (const auto pos = rest.find("no such subsection to be entered: "); pos != std::string::npos)
        {
          const std::string name = rest.substr(pos + 34);
          return at + "no subsection `" + shown_input(name) + "'" + where +
                 suggestion(name, declared_names(prm, {}, true)) + list_hint;
        }
      if (rest.rfind("The line <", 0) == 0 && rest.find("could not be parsed") != std::string::npos) // never echoed
        return at + "not a parameter line (expected `set Key = value', `subsection Name', `end' or `include "
                    "file')" + where;
      return at + shown_input(rest, 200) + where + list_hint;
    }

    // ---- JSON ---------------------------------------------------------------------------------------
    /// Refuses what boost's recursive parser should not see: a document that is not an object, or
    /// one nested deeper than input_limits::json_depth.
    void check_json_shape(const std::string &file, const std::string &text)
    {
      const auto first = text.find_first_not_of(" \t\r\n");
      if (first == std::string::npos || text[first] != '{')
        throw InputError(file + ": not a JSON object (a valve description is {\"Subsection\": {\"Key\": value}})");
      int depth = 0;
      bool in_string = false, escaped = false;
      for (char c : text)
        if (in_string)
          {
            if (escaped)
              escaped = false;
            else if (c == '\\')
              escaped = true;
            else if (c == '"')
              in_string = false;
          }
        else if (c == '"')
          in_string = true;
        else if ((c == '{' || c == '[') && ++depth > input_limits::json_depth)
          throw InputError(file + ": JSON nested deeper than " + std::to_string(input_limits::json_depth) +
                           " levels (a valve description has 3)");
        else if (c == '}' || c == ']')
          --depth;
    }

    /// Sets every entry of a JSON object tree: nested objects are subsections, a leaf (or an
    /// object with a "value" member, as `servodrift params --format json' writes) is an entry.
    void set_json_entries(ParameterHandler &prm, const ptree &tree, const std::string &file,
                          std::vector<std::string> &path, MovedEntries &moved)
    {
      for (const auto &[key, node] : tree)
        {
          const std::string entry = joined(path) + (path.empty() ? "" : "/") + shown_input(key);
          if (key.empty())
            throw InputError(file + ": `" + joined(path) + "' holds an array; entries are \"Key\": value");
          const auto value = node.get_child_optional("value");
          if (node.empty() || value)
            {
              if (path.empty())
                throw InputError(file + ": `" + entry + "' is a value at top level; every entry lives in a subsection");
              const std::string text = collapse_whitespace(value ? value->data() : node.data());
              if (moved.take(joined(path) + "/" + key, text, file))
                continue;
              try
                {
                  prm.set(key, text);
                }
              catch (const dealii::ExceptionBase &e)
                {
                  if (const auto pattern = mismatched_pattern(e))
                    throw InputError(file + ": `" + entry + "' = " + shown_input(text) + " is not allowed; allowed: " +
                                     *pattern);
                  throw InputError(file + ": no entry `" + entry + "'" +
                                   suggestion(key, declared_names(prm, path, false)) + list_hint);
                }
            }
          else
            {
              path.push_back(key);
              if (!prm.subsection_path_exists({key})) // relative to the subsection entered
                throw InputError(file + ": no subsection `" + entry + "'" +
                                 suggestion(key, declared_names(prm, {path.begin(), path.end() - 1}, true)) + list_hint);
              prm.enter_subsection(key);
              set_json_entries(prm, node, file, path, moved);
              prm.leave_subsection();
              path.pop_back();
            }
        }
    }

    void read_input_file(ParameterHandler &prm, const std::string &file)
    {
      const auto dot = file.rfind('.');
      const std::string extension = dot == std::string::npos ? "" : file.substr(dot);
      if (extension != ".prm" && extension != ".json" && file.find('=') != std::string::npos)
        throw InputError(shown_input(file) + ": given as the valve file, but it looks like an override; give each "
                                             "override its own --set");
      if (extension != ".prm" && extension != ".json")
        throw InputError(file + ": unknown parameter file format `" + shown_input(extension) +
                         "' (use a .prm or a .json file)");
      std::vector<std::string> chain;
      if (extension == ".prm")
        check_includes(file, chain);
      const std::string text = text_file(file, "a parameter file");
      MovedEntries moved;
      try
        {
          if (extension == ".prm")
            {
              std::istringstream in(without_moved_entries(text, file, moved));
              prm.parse_input(in, file);
            }
          else
            {
              check_json_shape(file, text);
              std::istringstream in(text);
              ptree tree;
              boost::property_tree::read_json(in, tree);
              std::vector<std::string> path;
              set_json_entries(prm, tree, file, path, moved);
            }
          moved.apply(prm);
        }
      catch (const InputError &)
        {
          throw;
        }
      catch (const dealii::ExceptionBase &e)
        {
          throw InputError(describe_parse_error(file, text, prm, e));
        }
      catch (const boost::property_tree::json_parser_error &e)
        {
          throw InputError(file + ":" + std::to_string(e.line()) + ": not valid JSON: " + shown_input(e.message()));
        }
      catch (const std::exception &e)
        {
          throw InputError(file + ": " + shown_input(e.what(), 200));
        }
    }

    /// Applies one "Subsection/Key=value" override.
    void apply_override(ParameterHandler &prm, const std::string &override_text)
    {
      const std::string where = "--set \"" + shown_input(override_text) + "\"";
      const auto eq = override_text.find('=');
      if (eq == std::string::npos)
        throw InputError(where + ": expected \"Subsection/Key=value\"");
      std::string path = override_text.substr(0, eq);
      const std::string value = collapse_whitespace(override_text.substr(eq + 1));
      std::vector<std::string> sections;
      for (std::size_t slash; (slash = path.find('/')) != std::string::npos; path = path.substr(slash + 1))
        sections.push_back(collapse_whitespace(path.substr(0, slash)));
      const std::string key = collapse_whitespace(path);
      if (sections.empty())
        throw InputError(where + ": expected \"Subsection/Key=value\"; every entry lives in a subsection");
      if (const RenamedEntry *moved = renamed_entry(joined(sections) + "/" + key))
        {
          warn_once(deprecation_warning(where, *moved));
          apply_override(prm, moved->new_path + "=" + value);
          return;
        }
      if (const RetiredEntry *gone = retired_entry(joined(sections) + "/" + key))
        {
          warn_once(retirement_warning(where, *gone));
          return;
        }
      for (std::size_t k = 1; k <= sections.size(); ++k)
        {
          const std::vector<std::string> head(sections.begin(), sections.begin() + k);
          if (prm.subsection_path_exists(head))
            continue;
          const std::vector<std::string> parent(sections.begin(), sections.begin() + k - 1);
          const auto entries = declared_names(prm, parent, false);
          if (std::find(entries.begin(), entries.end(), head.back()) != entries.end())
            throw InputError(where + ": `" + joined(head) + "' is an entry, not a subsection; expected "
                                     "\"Subsection/Key=value\"");
          throw InputError(where + ": no subsection `" + shown_input(joined(head)) + "'" +
                           suggestion(head.back(), declared_names(prm, parent, true)) + list_hint);
        }
      for (const auto &s : sections)
        prm.enter_subsection(s);
      std::string error;
      try
        {
          prm.set(key, value);
        }
      catch (const dealii::ExceptionBase &e)
        {
          if (const auto pattern = mismatched_pattern(e))
            error = where + ": `" + shown_input(value) + "' is not allowed; allowed: " + *pattern;
          else
            error = where + ": no entry `" + shown_input(key) + "' in subsection `" + joined(sections) + "'" +
                    suggestion(key, declared_names(prm, sections, false)) + list_hint;
        }
      for (std::size_t k = 0; k < sections.size(); ++k)
        prm.leave_subsection();
      if (!error.empty())
        throw InputError(error);
    }

  } // namespace

  void read_parameters(ParameterHandler &prm, const std::string &input_file, const std::vector<std::string> &overrides)
  {
    if (!input_file.empty())
      read_input_file(prm, input_file);
    for (const auto &o : overrides)
      apply_override(prm, o);
    check_numbers(prm);
  }
} // namespace servodrift
