#pragma once
// Entries that moved: a parameter file, a JSON description or a --set that names an entry by its
// old path is read as if it named the new one, with a one-line deprecation warning (the input
// readers, common/parameter_input.cc). The list is data: one row per moved entry.
#include <string>
#include <vector>

namespace servodrift
{
  struct RenamedEntry
  {
    std::string old_path; ///< "Subsection/.../Key" as files before the move spell it
    std::string new_path; ///< where the entry lives now
  };

  /// Every moved entry, in the order of their declarations
  const std::vector<RenamedEntry> &renamed_entries();

  /// The moved entry whose old path is `path', or nullptr
  const RenamedEntry *renamed_entry(const std::string &path);

  /// The one-line warning for a moved entry that `where' (a file and line, or a --set) still names
  std::string deprecation_warning(const std::string &where, const RenamedEntry &entry);
} // namespace servodrift
