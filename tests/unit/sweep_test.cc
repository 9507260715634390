// The sweep runner. These tests run serially and, as unit.sweep_two_ranks, under mpirun -np 2 (the
// tables of a whole 2-rank run are compared byte for byte by cli.mpi_two_ranks_byte_identical).
#include "common/sweep.h"

#include <gtest/gtest.h>

#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <set>
#include <string>
#include <thread>

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

TEST(Sweep, ACostlyCaseDoesNotHoldUpTheOthers)
{
  // Case 0 takes 0.5 s, the other eleven no time. Cases go to whichever rank is free, so on two
  // ranks the one that took case 0 computes nothing else: the other has finished cases 1-11 long
  // before (a fixed cyclic share would have given it cases 2, 4, ..., 10 as well). Each row says
  // which rank computed it.
  const std::size_t n = 12;
  const auto rows = run_sweep(
    "test", n,
    [](std::size_t k) {
      if (k == 0)
        std::this_thread::sleep_for(std::chrono::milliseconds(500));
      return CaseRows{{double(k), double(mpi_rank())}};
    },
    OutputParameters::Progress::none);
  ASSERT_EQ(rows.size(), n);
  std::set<double> ranks_of_the_others;
  for (std::size_t k = 0; k < n; ++k)
    {
      EXPECT_EQ(rows[k][0], double(k)) << "rows in case order, each case once";
      if (k > 0)
        ranks_of_the_others.insert(rows[k][1]);
    }
  if (mpi_size() > 1) // the sharing out; on one rank, the rows alone
    {
      EXPECT_EQ(ranks_of_the_others.count(rows[0][1]), 0u) << "the rank busy with case 0 took no other case";
    }
}

TEST(Sweep, BroadcastBytesHandsOneRanksResultToAll)
{
  // what the flow stage does with the orifice path's states: the rank that computed a case's
  // result (here the last rank) hands it to every rank; the others pass nothing
  const unsigned int root = mpi_size() - 1;
  std::vector<char> bytes;
  if (mpi_rank() == root)
    for (int k = 0; k < 100000; ++k) // larger than one message buffer
      bytes.push_back(char(k % 251));
  const std::vector<char> received = broadcast_bytes(bytes, root);
  ASSERT_EQ(received.size(), 100000u);
  for (int k = 0; k < 100000; k += 997)
    EXPECT_EQ(received[std::size_t(k)], char(k % 251));
}

// CHOLMOD's supernodal factorisation asks libgomp for teams of 4; with max-active-levels 0 no region
// becomes active and every team has one thread (OpenMP 5.1, 2.6.1). A user's OMP_THREAD_LIMIT stands.
TEST(OpenMPTeams, OneThreadPerProcessUnlessTheUserSetsALimit)
{
  const char *set = std::getenv("OMP_THREAD_LIMIT");
  const std::string user_limit = set ? set : "";
  const int levels = omp_get_max_active_levels();

  ::setenv("OMP_THREAD_LIMIT", "4", 1);
  omp_set_max_active_levels(8);
  servodrift::one_thread_per_process();
  EXPECT_EQ(omp_get_max_active_levels(), 8);

  ::unsetenv("OMP_THREAD_LIMIT");
  servodrift::one_thread_per_process();
  EXPECT_EQ(omp_get_max_active_levels(), 0);

  if (set)
    ::setenv("OMP_THREAD_LIMIT", user_limit.c_str(), 1);
  omp_set_max_active_levels(levels);
}
