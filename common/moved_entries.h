#pragma once
// Reading moved entries (common/parameters/renamed_entries.h) from a valve description: the values
// a file sets under old paths, taken out while deal.II reads it and set at their new paths after,
// each with its one-line deprecation warning (common/parameter_input.cc reads through these).
#include <set>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace servodrift
{
  struct RenamedEntry;

  /// Prints a warning on rank 0, each distinct one once per process (a run reads its description
  /// more than once)
  void warn_once(const std::string &line);

  /// The values a parameter file sets under moved entries' old paths: taken out while the file is
  /// read, set at their new paths afterwards, each with its deprecation warning.
  class MovedEntries
  {
  public:
    /// `path' set in the file at `where'; true (and the value kept) if it is a moved entry's old path,
    /// or true (and the value dropped) if it is a retired entry
    bool take(const std::string &path, const std::string &value, const std::string &where);
    /// Sets the values taken at their new paths, and warns of the retired entries set. Throws
    /// InputError if the file also sets the new path (one entry set twice under two names) or
    /// deal.II refuses the value.
    void apply(dealii::ParameterHandler &prm) const;

  private:
    struct Value
    {
      const RenamedEntry *entry;
      std::string value, where;
    };
    std::vector<Value> values;
    std::vector<std::string> retired; ///< the warnings of the retired entries taken
    std::set<std::string> set_paths;
  };

  /// The PRM text with every `set' of a moved entry blanked (its lines kept, so that deal.II's
  /// line numbers stay the file's), the values taken by `moved'.
  std::string without_moved_entries(const std::string &text, const std::string &file, MovedEntries &moved);
} // namespace servodrift
