#pragma once
// Measured drift data for the calibrate mutations: made by the product itself (a run with a known
// magnetic null), held as cells so that one cell, row or header item can be broken.
#include "fuzz_mutations.h"
#include "fuzz_process.h"

#include <string>
#include <vector>

namespace fuzz
{
  /// Fills c's measured data from the drift map of a run in `work' with a known magnetic null; returns
  /// what went wrong ("" if nothing), with that run's outcome in `o'.
  std::string make_measured_data(Context &c, const fs::path &work, double timeout, Outcome &o);

  /// A number as a measured file writes it (9 digits).
  std::string num(double x);

  /// A measured-data CSV file as cells.
  struct Measured
  {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;

    std::string text() const;
  };

  /// The valid file in one of three forms: 0, null-shift currents in mA with standard deviations; 1, in
  /// A without (tests/cli/calibrate_example.sh); 2, as 0 with brake pressures at the rated current in MPa.
  Measured valid_data(const Context &c, int form);
} // namespace fuzz
