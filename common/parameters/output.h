#pragma once
#include <string>
#include <vector>
namespace dealii { class ParameterHandler; }

namespace servodrift
{
  /// Subsection "Output". Nothing here changes a number, so this subsection is left out of the
  /// parameters hash stamped on every table.
  struct OutputParameters
  {
    static constexpr const char *subsection = "Output";
    std::string directory;            ///< every output goes below this directory
    bool plots;                       ///< write gnuplot plots
    std::vector<std::string> plot_formats; ///< "png", "svg"
    enum class Progress { automatic, lines, none };
    Progress progress;

    static void declare_parameters(dealii::ParameterHandler &prm);
    void parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace servodrift
