#pragma once
#include <array>
#include <string>
#include <vector>
namespace dealii { class ParameterHandler; }
namespace servodrift { class ParameterSource; }

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
    /// Field-level cases whose fields are written as VTU: (temperature [degC], angle [rad],
    /// current [A]) of the torque-motor sweep; `all_field_cases' writes every case.
    std::vector<std::array<double, 3>> magnetics_field_cases;
    bool all_magnetics_fields;
    /// Field-level flow cases written as VTU under flow/: those at the reference temperature, all, none
    enum class FlowFields { reference, all, none };
    FlowFields flow_fields;
    bool fmu;                         ///< `servodrift run' also exports the valve as an FMU
    bool mat_tables;                  ///< tables/servodrift_tables.mat (MATLAB MAT v5)
    bool modelica_tables;             ///< tables/servodrift_tables.txt (Modelica text tables)

    static void declare_parameters(dealii::ParameterHandler &prm);
    void parse_parameters(ParameterSource &prm);
  };
} // namespace servodrift
