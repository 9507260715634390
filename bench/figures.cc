#include "bench/figures.h"

#include "common/csv.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace servodrift::bench
{
  namespace
  {
    // The rank under mpirun, from Open MPI's environment: the figures need no MPI (bench_fmu links none)
    bool first_rank()
    {
      const char *rank = std::getenv("OMPI_COMM_WORLD_RANK");
      return !rank || std::atoi(rank) == 0;
    }
  } // namespace

  Figures::Figures(int argc, char **argv)
    : driver(std::filesystem::path(argv[0]).filename().string())
    , command("build/bench/" + driver)
  {
    for (int k = 1; k < argc; ++k)
      command += std::string(" ") + argv[k];
    if (const char *prefix = std::getenv("SERVODRIFT_BENCH_PREFIX")) // how the runner started it (mpirun -np 2, ...)
      if (*prefix)
        command = std::string(prefix) + " " + command;
    // a new run of the driver starts its file afresh
    if (const char *directory = std::getenv("SERVODRIFT_BENCH_RESULTS"); directory && *directory && first_rank())
      {
        std::filesystem::create_directories(directory);
        std::ofstream(std::filesystem::path(directory) / (driver + ".csv"), std::ios::trunc);
      }
  }

  void Figures::record(const std::string &figure, const std::string &target, const std::string &measured) const
  {
    if (!first_rank())
      return;
    std::printf("[ figure ] %s | %s | %s | %s\n", figure.c_str(), target.c_str(), measured.c_str(), command.c_str());
    const char *directory = std::getenv("SERVODRIFT_BENCH_RESULTS");
    if (!directory || !*directory)
      return;
    std::ofstream out(std::filesystem::path(directory) / (driver + ".csv"), std::ios::app);
    out << quoted_csv_field(driver) << ',' << quoted_csv_field(figure) << ',' << quoted_csv_field(target) << ',' << quoted_csv_field(measured)
        << ',' << quoted_csv_field(command) << '\n';
  }

  std::string seconds(double s)
  {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, s < 1e-3 ? "%.3g us" : s < 1 ? "%.3g ms" : "%.3g s",
                  s < 1e-3 ? s * 1e6 : s < 1 ? s * 1e3 : s);
    return buffer;
  }
} // namespace servodrift::bench
