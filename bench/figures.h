#pragma once
// The figures a benchmark measures, as doc/performance.md shows them: figure | target | measured |
// command. Each driver records its figures here; they are printed, and appended to
// $SERVODRIFT_BENCH_RESULTS/<driver>.csv when that is set (scripts/run-benchmarks sets it to
// doc/benchmarks/, from which scripts/render-docs renders the doc's tables). Under mpirun the first
// rank records.
#include <string>

namespace servodrift::bench
{
  class Figures
  {
  public:
    /// The driver's name and its command line, from its arguments (argv[0] is the driver's name).
    Figures(int argc, char **argv);
    /// One figure: what is measured, the target it must reach ("no target" when none) and the value.
    void record(const std::string &figure, const std::string &target, const std::string &measured) const;

  private:
    std::string driver;
    std::string command;
  };

  /// A wall time as the tables show it: 3 significant digits and the unit.
  std::string seconds(double s);
} // namespace servodrift::bench
