#pragma once
// Helpers shared by the test programs: the built-in valve with overrides, and the four reduced-order
// tables written to a fresh directory for the system-model tests.
#include "common/valve_description.h"

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
  /// A fresh, empty temporary directory (removed at the end of a passing test program).
  std::string temporary_directory();
  /// Removes every directory temporary_directory() made in this process (the test main calls it
  /// when all tests passed; a failure keeps them for inspection).
  void remove_temporary_directories();
  /// Relative difference |a - b|/|b|.
  double relative(double a, double b);
  /// A measured value as a test records it (RecordProperty): 6 significant digits.
  std::string number(double value);
} // namespace servodrift::test
