// The sweep runner (serial path; the 2-rank path is checked byte for byte by a ctest with mpirun).
#include "common/sweep.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace servodrift;

TEST(Sweep, RowsComeInCaseOrder)
{
  const auto rows = run_sweep(
    "test", 5, [](std::size_t k) { return CaseRows{{double(k), 1.0}, {double(k), 2.0}}; },
    OutputParameters::Progress::none);
  ASSERT_EQ(rows.size(), 10u);
  for (std::size_t r = 0; r < rows.size(); ++r)
    {
      EXPECT_EQ(rows[r][0], double(r / 2));
      EXPECT_EQ(rows[r][1], double(1 + r % 2));
    }
}

TEST(Sweep, AFailingCaseFailsTheSweepWithItsMessage)
{
  try
    {
      run_sweep(
        "test", 4,
        [](std::size_t k) -> CaseRows {
          if (k == 2)
            throw std::runtime_error("case 2 broke");
          return {{0.0}};
        },
        OutputParameters::Progress::none);
      FAIL();
    }
  catch (const std::runtime_error &e)
    {
      EXPECT_STREQ(e.what(), "case 2 broke");
    }
}
