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

  /// An entry no longer read: a description that sets it reads as one that does not, with a
  /// one-line warning saying why (a run's results no longer depend on it).
  struct RetiredEntry
  {
    std::string path; ///< "Subsection/.../Key"
    std::string why;  ///< what took its place
  };

  /// Every retired entry
  const std::vector<RetiredEntry> &retired_entries();

  /// The retired entry at `path', or nullptr
  const RetiredEntry *retired_entry(const std::string &path);

  /// The one-line warning for a retired entry that `where' still sets
  std::string retirement_warning(const std::string &where, const RetiredEntry &entry);
} // namespace servodrift
