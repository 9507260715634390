#pragma once
// Helpers of the tests that link only the valve's lean core (core_tests): temporary directories,
// RV-1 read from examples/rv1.prm without deal.II, relative differences.
#include "common/valve_description.h"

#include <functional>
#include <string>

// A test that takes 20 s or more on the 2-core machine: as TEST and TEST_P, and ctest labels it (and
// every instance of a parameterised one) `slow' as well, read from this mark in the test's source
// (tests/slow_gtests.cmake), so that `ctest -LE slow' leaves it out.
#define SLOW_TEST(suite, name) TEST(suite, name)
#define SLOW_TEST_P(suite, name) TEST_P(suite, name)

namespace servodrift::test
{
  /// A fresh, empty temporary directory (removed at the end of a passing test program).
  std::string temporary_directory();
  /// Removes every directory temporary_directory() made in this process (the test main calls it
  /// when all tests passed; a failure keeps them for inspection).
  void remove_temporary_directories();
  /// `text' written to the file `name' in a fresh temporary directory; its path
  std::string write_file(const std::string &name, const std::string &text);
  /// The message of the InputError that `f' throws, checked to be one line; "" and a test failure
  /// if it throws none.
  std::string input_refusal(const std::function<void()> &f);
  /// RV-1 as examples/rv1.prm prints it (`servodrift params', kept in sync by cli.files_in_sync),
  /// read by the lean reader: the defaults without deal.II.
  ValveDescription rv1();
  /// Relative difference |a - b|/|b|.
  double relative(double a, double b);
  /// A measured value as a test records it (RecordProperty): 6 significant digits.
  std::string number(double value);
} // namespace servodrift::test
