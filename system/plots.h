#pragma once
// gnuplot plots of the drift maps and stage coefficients: data (.dat) and scripts (.gp) always,
// images (PNG/SVG) when gnuplot is installed. Each image is written to a temporary name and renamed.
#include "common/valve_description.h"

#include <string>
#include <vector>

namespace servodrift::system
{
  struct SystemResults;

  struct PlotFiles
  {
    std::vector<std::string> images; ///< paths relative to the output directory
    std::string problem;             ///< empty, or why no images were made
  };

  PlotFiles write_plots(const ValveDescription &valve, const SystemResults &results, const std::string &directory);
} // namespace servodrift::system
