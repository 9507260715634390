#pragma once
// Helpers of the checks of a valve description that go beyond one entry's range (the structs'
// validate members, common/parameters/*_validation.cc, and common/valve_validation.cc). Internal to
// servodrift_core: include it only from .cc files.
#include "common/error.h"

#include <cstddef>
#include <string>
#include <vector>

namespace servodrift::validation
{
  /// Throws InputError with `entry' in quotes followed by `what': the message names the entry the user
  /// has to change.
  [[noreturn]] inline void refuse(const std::string &entry, const std::string &what)
  {
    throw InputError("`" + entry + "' " + what);
  }

  /// Refuses `entry' unless `list' is strictly increasing; the message shows the values divided by
  /// `scale' (the declared unit, e.g. units::degree for a list stored in rad).
  inline void require_increasing(const std::vector<double> &list, const std::string &entry, double scale = 1.0)
  {
    for (std::size_t k = 1; k < list.size(); ++k)
      if (!(list[k] > list[k - 1]))
        refuse(entry, "must be strictly increasing, but " + format_number(list[k - 1] / scale) +
                        " is followed by " + format_number(list[k] / scale));
  }
} // namespace servodrift::validation
