#pragma once
// Helpers shared by the test programs: the built-in valve with overrides, and the four reduced-order
// tables written to a fresh directory for the system-model tests.
#include "common/valve_description.h"
#include "tests/support/core_support.h"

#include <string>
#include <vector>

namespace servodrift::test
{
  /// RV-1 with overrides ("Subsection/Key=value"); output into a fresh temporary directory. Every
  /// stage is at its reduced-order level and `Dynamics/Enabled' is false unless the overrides say
  /// otherwise.
  ValveDescription valve(std::vector<std::string> overrides = {});
  /// Runs the three reduced-order stages for `valve' (into valve.output.directory) and returns
  /// the tables directory.
  std::string write_reduced_order_tables(const ValveDescription &valve);
} // namespace servodrift::test
