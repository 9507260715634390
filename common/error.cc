#include "common/error.h"

#include <cstdio>

namespace servodrift
{
  std::string format_number(double value)
  {
    char buffer[64];
    std::snprintf(buffer, sizeof(buffer), "%.6g", value);
    return buffer;
  }
} // namespace servodrift
