#pragma once
#include <string>

namespace servodrift
{
  /// Project version (CMake project version).
  const char *version();
  /// Short git revision of the source tree at build time, "-dirty" if it had uncommitted changes.
  const char *git_revision();
  /// "servodrift 0.1.0 (git 1a2b3c4) <what>": the producer line of tables and outputs.
  std::string producer_string(const std::string &what);
} // namespace servodrift
