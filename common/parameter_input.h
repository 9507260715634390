#pragma once
// Reading a valve description into deal.II's ParameterHandler: the input file (.prm or .json) and
// the --set overrides. Whatever the input, the outcome is the filled handler or an InputError of one
// line that names the file or override, the entry and the allowed range: no crash (recursion is
// bounded: include depth, JSON depth), no raw library message, no echo of long or binary text.
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace servodrift
{
  /// Reads `input_file' (if not empty) into `prm', then applies each "Subsection/Key=value" of
  /// `overrides' in order; then checks that every number converts (a subnormal passes deal.II's
  /// pattern but not its conversion). `prm' must hold the declarations. Throws InputError.
  void read_parameters(dealii::ParameterHandler &prm, const std::string &input_file,
                       const std::vector<std::string> &overrides);

  /// `path' ("Subsection/Key"), or its new path if it names a moved entry
  /// (common/parameters/renamed_entries.h), with a one-line deprecation warning naming `where'.
  std::string current_entry_path(const std::string &path, const std::string &where);

  /// User text as a message may show it: whitespace runs as one space, other control or non-ASCII
  /// bytes as '?', at most `limit' characters (then "... (N characters)").
  std::string shown_input(const std::string &text, std::size_t limit = 80);

  /// Whitespace runs as one space, leading and trailing whitespace removed.
  std::string collapse_whitespace(const std::string &text);

  /// Limits of what a parameter file may be (issue 24): nesting beyond these is refused, not
  /// followed.
  namespace input_limits
  {
    constexpr int include_depth = 8;
    constexpr int json_depth = 16;
    constexpr std::size_t file_bytes = 4u << 20; ///< a parameter file is a few kB
  } // namespace input_limits
} // namespace servodrift
