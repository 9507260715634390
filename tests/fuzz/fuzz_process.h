#pragma once
// Running the product: one child process in its own directory and process group, with a timeout.
#include "fuzz_support.h"

#include <string>
#include <vector>

namespace fuzz
{
  // ---- running the product ------------------------------------------------------------------------
  struct Outcome
  {
    bool timed_out = false;
    int exit_code = -1; ///< when it exited
    int signal = 0;     ///< when a signal ended it
    double seconds = 0;
    std::string out, err;
  };

  /// Runs argv in `cwd' as the leader of its own process group, stdin from /dev/null, stdout and
  /// stderr to files in `cwd'. After `timeout' seconds the whole group is killed (servodrift
  /// re-executes itself and an MPI singleton may start helpers: killing the leader alone would leave
  /// them).
  Outcome run_process(const std::vector<std::string> &argv, const fs::path &cwd, double timeout);
} // namespace fuzz
