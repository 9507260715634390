#include "common/version.h"

namespace servodrift
{
  std::string producer_string(const std::string &what)
  {
    return std::string("servodrift ") + version() + " (git " + git_revision() + ") " + what;
  }
} // namespace servodrift
