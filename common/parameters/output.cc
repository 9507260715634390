#include "common/parameters/output.h"

#include "common/parameters/parameter_helpers.h"

#include <deal.II/base/utilities.h>

namespace servodrift
{
  using namespace parameters;

  void OutputParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    prm.declare_entry("Directory", "servodrift-out", Patterns::DirectoryName(),
                      "Output directory; tables/, system/ and report.md go below it (the command "
                      "line's -o overrides it). [-]");
    prm.declare_entry("Plots", "true", Patterns::Bool(), "Write gnuplot plots of the drift maps. [-]");
    prm.declare_entry("Plot formats", "png, svg", Patterns::MultipleSelection("png|svg"),
                      "Image formats of the plots. [-]");
    prm.declare_entry("Progress", "auto", Patterns::Selection("auto|lines|none"),
                      "Progress of long sweeps on stderr: auto (an updating line on a terminal, plain "
                      "lines otherwise), lines, or none. [-]");
    prm.leave_subsection();
  }

  void OutputParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    directory = prm.get("Directory");
    plots = prm.get_bool("Plots");
    plot_formats = dealii::Utilities::split_string_list(prm.get("Plot formats"));
    const std::string p = prm.get("Progress");
    progress = p == "auto" ? Progress::automatic : p == "lines" ? Progress::lines : Progress::none;
    prm.leave_subsection();
  }
} // namespace servodrift
