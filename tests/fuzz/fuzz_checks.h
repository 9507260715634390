#pragma once
// The checks of one run: the output directory before and after, non-finite numbers, leftovers, stderr.
#include "fuzz_mutations.h"
#include "fuzz_process.h"
#include "fuzz_support.h"

#include <map>
#include <string>
#include <vector>

namespace fuzz
{
  // ---- the output directory ------------------------------------------------------------------------------
  /// A recursive listing: relative path -> "dir", "link:<target>" or "file:<FNV-1a of the bytes>".
  /// An absent directory is an empty map with `exists' false.
  struct Snapshot
  {
    bool exists = false;
    std::map<std::string, std::string> entries;
  };

  Snapshot snapshot(const fs::path &dir);

  /// The first non-finite number token (nan, inf, infinity, any case and sign, as a whole token
  /// between characters that are not letters, digits or '_') in the .csv, .json and .md files under
  /// `dir', as "file:line: token"; empty if none.
  std::string non_finite_token(const fs::path &dir);

  // ---- checks -----------------------------------------------------------------------------------------
  struct Failure
  {
    std::string kind, detail;
  };

  /// The failures of one run (none if it kept every promise); `before' is the output directory's
  /// snapshot before the run.
  std::vector<Failure> check(const Mutation &m, const Outcome &o, const Snapshot &before, const fs::path &out_dir);
} // namespace fuzz
