#include "common/parameters/output.h"

#include "common/parameters/parameter_helpers.h"

#include <deal.II/base/utilities.h>

#include "common/error.h"
#include "common/units.h"

#include <cstdlib>

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
    prm.declare_entry("Magnetics fields", "40 0 0, 40 0.1 0, 40 0 0.02, 120 0.1 0.02",
                      Patterns::Anything(),
                      "Torque-motor field-level cases written as VTU files (A_z, B, |B|, H, material, "
                      "current density) with a .pvd collection under magnetics/: a comma-separated list "
                      "of `temperature angle current' triples in degC, deg and A that are points of the "
                      "sweep, or `all', or `none'. [-]");
    prm.declare_entry("Flow fields", "reference", Patterns::Selection("reference|all|none"),
                      "Field-level flow cases written as VTU files (p, velocity, k, epsilon, mu_t, y+) with "
                      ".pvd collections under flow/: those at the table temperature nearest the reference "
                      "temperature (a few MB each), all, or none. [-]");
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
    const std::string flow = prm.get("Flow fields");
    flow_fields = flow == "all" ? FlowFields::all : flow == "none" ? FlowFields::none : FlowFields::reference;
    const std::string fields = dealii::Utilities::trim(prm.get("Magnetics fields"));
    all_magnetics_fields = fields == "all";
    magnetics_field_cases.clear();
    if (fields != "all" && fields != "none" && !fields.empty())
      for (const std::string &triple : dealii::Utilities::split_string_list(fields, ','))
        {
          const auto numbers = dealii::Utilities::split_string_list(triple, ' ');
          std::vector<double> v;
          for (const auto &n : numbers)
            if (!n.empty())
              {
                char *end = nullptr;
                v.push_back(std::strtod(n.c_str(), &end));
                if (*end != '\0')
                  v.clear(), v.push_back(0), v.push_back(0), v.push_back(0), v.push_back(0);
              }
          if (v.size() != 3)
            throw InputError("`Output/Magnetics fields': `" + triple +
                             "' is not a `temperature angle current' triple (degC deg A), `all' or `none'");
          magnetics_field_cases.push_back({v[0], v[1] * units::degree, v[2]});
        }
    prm.leave_subsection();
  }
} // namespace servodrift
