#include "common/parameters/output.h"

#include "common/error.h"
#include "common/parameters/parameter_source.h"
#include "common/units.h"

#include <algorithm>
#include <cstdlib>

namespace servodrift
{
  using namespace parameters;

  void OutputParameters::parse_parameters(ParameterSource &prm)
  {
    prm.enter_subsection(subsection);
    directory = prm.get("Directory");
    plots = prm.get_bool("Plots");
    plot_formats = split_list(prm.get("Plot formats"));
    const std::string p = prm.get("Progress");
    progress = p == "auto" ? Progress::automatic : p == "lines" ? Progress::lines : Progress::none;
    const std::string flow = prm.get("Flow fields");
    flow_fields = flow == "all" ? FlowFields::all : flow == "none" ? FlowFields::none : FlowFields::reference;
    fmu = prm.get_bool("FMU");
    const std::vector<std::string> formats = split_list(prm.get("Formats"));
    mat_tables = std::find(formats.begin(), formats.end(), "mat") != formats.end();
    modelica_tables = std::find(formats.begin(), formats.end(), "modelica") != formats.end();
    const std::string fields = trimmed(prm.get("Magnetics fields"));
    all_magnetics_fields = fields == "all";
    magnetics_field_cases.clear();
    if (fields != "all" && fields != "none" && !fields.empty())
      for (const std::string &triple : split_list(fields, ','))
        {
          const auto numbers = split_list(triple, ' ');
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
