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

  /// A gnuplot plot: the commands after the terminal and output lines.
  struct Plot
  {
    std::string name, body;
  };
  /// Writes <name>.<format>.gp for every plot and `Output/Plot formats' into `directory' and renders
  /// it with gnuplot where gnuplot is installed; adds the images (relative to the output directory)
  /// and any problem to `files'.
  void render_plots(const ValveDescription &valve, const std::vector<Plot> &plots, const std::string &directory,
                    PlotFiles &files);
  /// Up to five indices of a list of n: both ends, the middle and the quartiles.
  std::vector<std::size_t> representative_indices(std::size_t n);
} // namespace servodrift::system
