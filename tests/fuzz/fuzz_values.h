#pragma once
// Mutated values: random bytes, bad values for an entry, misspelled names.
#include "fuzz_support.h"

#include <cstddef>
#include <string>
#include <vector>

namespace fuzz
{
  // ---- mutated values --------------------------------------------------------------------------------
  std::string random_bytes(Rng &rng, std::size_t n, bool allow_nul);

  /// Bytes that pass a "no control characters" test but are no UTF-8: they reach past a text check.
  std::string high_bytes(Rng &rng, std::size_t n);

  struct Replacement
  {
    std::string value, label;
  };

  /// One bad value for an entry (brief, mutation 1): small integers, scaled values, extremes,
  /// non-finite and subnormal numbers, empty, huge, binary, a huge list, another entry's value.
  Replacement bad_value(Rng &rng, const std::string &original, const std::vector<std::string> &other_values);

  std::string misspelled(Rng &rng, std::string name);
} // namespace fuzz
