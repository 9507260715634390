#pragma once
// The checks doc/validation.md shows. Each compares a value the test measured with a reference
// within a tolerance (a gtest expectation, failing the test where it is called) and records the row
// it makes in the doc: check | reference | tolerance | value | test. The row goes to
// $SERVODRIFT_CHECKS/<test>.csv when that is set (scripts/run-tests sets it for a whole run);
// scripts/render-docs renders doc/validation.md's tables from those files and ctest's record of
// which tests passed. The tolerance in the doc is therefore the one asserted.
#include "common/error.h" // format_number, for the checks' names

#include <string>

/// |measured - reference| <= tolerance |reference|
#define EXPECT_CHECK_RELATIVE(check, measured, reference, tolerance, source)                                      \
  ::servodrift::test::check_relative(__FILE__, __LINE__, check, measured, reference, tolerance, source)
/// |measured - reference| <= tolerance
#define EXPECT_CHECK_ABSOLUTE(check, measured, reference, tolerance, source)                                      \
  ::servodrift::test::check_absolute(__FILE__, __LINE__, check, measured, reference, tolerance, source)
/// measured <= limit
#define EXPECT_CHECK_AT_MOST(check, measured, limit, source)                                                       \
  ::servodrift::test::check_at_most(__FILE__, __LINE__, check, measured, limit, source)
/// measured >= limit
#define EXPECT_CHECK_AT_LEAST(check, measured, limit, source)                                                      \
  ::servodrift::test::check_at_least(__FILE__, __LINE__, check, measured, limit, source)

namespace servodrift::test
{
  void check_relative(const char *file, int line, const std::string &check, double measured, double reference,
                      double tolerance, const std::string &source);
  void check_absolute(const char *file, int line, const std::string &check, double measured, double reference,
                      double tolerance, const std::string &source);
  void check_at_most(const char *file, int line, const std::string &check, double measured, double limit,
                     const std::string &source);
  void check_at_least(const char *file, int line, const std::string &check, double measured, double limit,
                      const std::string &source);
  /// A row whose comparison the test makes itself (a property over many values, a set of figures):
  /// the reference, the tolerance and the value as the doc shows them.
  void record_check(const std::string &check, const std::string &reference, const std::string &tolerance,
                    const std::string &value);
  /// A measured value as the doc shows it: 4 significant digits, the precision the references carry
  /// and one that does not change with a machine's rounding.
  std::string shown(double value);
  /// The larger (smaller) of two values, NaN winning: the worst case of a loop, checked once, keeps a
  /// failed point (NaN) failed.
  double larger(double a, double b);
  double smaller(double a, double b);
} // namespace servodrift::test
