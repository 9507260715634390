#pragma once
// Helpers shared by the test programs: the built-in valve with overrides, and the four reduced-order
// tables written to a fresh directory for the system-model tests.
#include "common/valve_description.h"

#include <string>
#include <vector>

namespace servodrift::test
{
  /// RV-1 with overrides ("Subsection/Key=value"); output into a fresh temporary directory. The
  /// torque motor and the spring tube are at their reduced-order level unless the overrides say otherwise.
  ValveDescription valve(std::vector<std::string> overrides = {});
  /// Runs the three reduced-order stages for `valve' (into valve.output.directory) and returns
  /// the tables directory.
  std::string write_reduced_order_tables(const ValveDescription &valve);
  /// A fresh, empty temporary directory.
  std::string temporary_directory();
  /// Relative difference |a - b|/|b|.
  double relative(double a, double b);
} // namespace servodrift::test
