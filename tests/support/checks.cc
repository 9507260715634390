#include "tests/support/checks.h"

#include "common/csv.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>

namespace servodrift::test
{
  namespace
  {
    std::string printed(double value, const char *format)
    {
      char buffer[48];
      std::snprintf(buffer, sizeof(buffer), format, value);
      return buffer;
    }

    std::string percent_or_fraction(double tolerance)
    {
      return tolerance >= 1e-3 ? printed(100 * tolerance, "%.3g") + " %" : printed(tolerance, "%.1e") + " rel.";
    }

    std::string with_source(double reference, const std::string &source)
    {
      return printed(reference, "%.6g") + (source.empty() ? "" : " (" + source + ")");
    }
  } // namespace

  std::string shown(double value) { return std::isfinite(value) ? printed(value, "%.4g") : "not finite"; }

  double larger(double a, double b)
  {
    return std::isnan(a) || std::isnan(b) ? std::numeric_limits<double>::quiet_NaN() : std::max(a, b);
  }

  double smaller(double a, double b)
  {
    return std::isnan(a) || std::isnan(b) ? std::numeric_limits<double>::quiet_NaN() : std::min(a, b);
  }

  void record_check(const std::string &check, const std::string &reference, const std::string &tolerance,
                    const std::string &value)
  {
    const auto *info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string test = std::string(info->test_suite_name()) + "." + info->name();
    std::printf("[ check    ] %s | %s | %s | %s\n", check.c_str(), reference.c_str(), tolerance.c_str(), value.c_str());
    const char *directory = std::getenv("SERVODRIFT_CHECKS");
    if (!directory || !*directory)
      return;
    // one file per test, started afresh by the test's first check in this process
    static std::set<std::string> started;
    std::string file = test;
    for (char &c : file)
      if (c == '/')
        c = '_';
    std::filesystem::create_directories(directory);
    const auto path = std::filesystem::path(directory) / (file + ".csv");
    std::ofstream out(path, started.insert(test).second ? std::ios::trunc : std::ios::app);
    out << quoted_csv_field(test) << ',' << quoted_csv_field(check) << ',' << quoted_csv_field(reference) << ','
        << quoted_csv_field(tolerance) << ',' << quoted_csv_field(value) << '\n';
  }

  void check_relative(const char *file, int line, const std::string &check, double measured, double reference,
                      double tolerance, const std::string &source)
  {
    const double error = std::abs(measured - reference) / std::abs(reference);
    if (!(error <= tolerance))
      ADD_FAILURE_AT(file, line) << check << ": " << measured << " against " << reference << ", relative error "
                                 << error << " > " << tolerance;
    record_check(check, with_source(reference, source), percent_or_fraction(tolerance), shown(measured));
  }

  void check_absolute(const char *file, int line, const std::string &check, double measured, double reference,
                      double tolerance, const std::string &source)
  {
    const double error = std::abs(measured - reference);
    if (!(error <= tolerance))
      ADD_FAILURE_AT(file, line) << check << ": " << measured << " against " << reference << ", error " << error
                                 << " > " << tolerance;
    record_check(check, with_source(reference, source), "± " + printed(tolerance, "%.6g"), shown(measured));
  }

  void check_at_most(const char *file, int line, const std::string &check, double measured, double limit,
                     const std::string &source)
  {
    if (!(measured <= limit))
      ADD_FAILURE_AT(file, line) << check << ": " << measured << " > " << limit;
    record_check(check, source, "at most " + printed(limit, "%.6g"), shown(measured));
  }

  void check_at_least(const char *file, int line, const std::string &check, double measured, double limit,
                      const std::string &source)
  {
    if (!(measured >= limit))
      ADD_FAILURE_AT(file, line) << check << ": " << measured << " < " << limit;
    record_check(check, source, "at least " + printed(limit, "%.6g"), shown(measured));
  }
} // namespace servodrift::test
