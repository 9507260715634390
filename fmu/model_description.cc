#include "fmu/model_description.h"

#include <algorithm>
#include <sstream>

namespace servodrift::fmu
{
  namespace
  {
    std::string escaped(const std::string &text)
    {
      std::string out;
      for (char c : text)
        switch (c)
          {
          case '&': out += "&amp;"; break;
          case '<': out += "&lt;"; break;
          case '>': out += "&gt;"; break;
          case '"': out += "&quot;"; break;
          default: out += c;
          }
      return out;
    }

    std::string number(double value)
    {
      std::ostringstream s;
      s.precision(17);
      s << value;
      return s.str();
    }

    std::string list(const std::vector<std::size_t> &indices)
    {
      std::string s;
      for (std::size_t i : indices)
        s += (s.empty() ? "" : " ") + std::to_string(i);
      return s;
    }

    const char *causality(Role role)
    {
      switch (role)
        {
        case Role::state:
        case Role::derivative: return "local";
        case Role::input: return "input";
        case Role::output: return "output";
        case Role::parameter: return "parameter";
        }
      return "local";
    }

    /// The 1-based ScalarVariable indices of a role's variables, or of some of them by their number
    struct Indices
    {
      const Layout &layout;
      std::vector<std::size_t> all(Role role) const
      {
        std::vector<std::size_t> out;
        for (std::size_t k = 0; k < layout.variables.size(); ++k)
          if (layout.variables[k].role == role)
            out.push_back(k + 1);
        return out;
      }
      std::size_t of(Role role, std::size_t number) const { return layout.first(role) + number + 1; }
      std::size_t of(Input i) const { return of(Role::input, static_cast<std::size_t>(i)); }
      std::size_t state(std::size_t k) const { return of(Role::state, k); }
    };

    std::vector<std::size_t> joined(std::vector<std::size_t> a, const std::vector<std::size_t> &b)
    {
      a.insert(a.end(), b.begin(), b.end());
      std::sort(a.begin(), a.end());
      a.erase(std::unique(a.begin(), a.end()), a.end());
      return a;
    }

    /// What each output reads (model.md E30, E33, E36): its states and inputs
    std::vector<std::size_t> output_dependencies(const Indices &x, Output o)
    {
      const std::vector<std::size_t> pressures_and_port = {x.of(Input::supply_pressure), x.of(Input::return_pressure),
                                                           x.of(Input::oil_temperature),
                                                           x.of(Input::brake_port_pressure)};
      switch (o)
        {
        case Output::brake_pressure: return {x.state(6), x.of(Input::brake_port_pressure)};
        case Output::brake_flow:
        case Output::supply_flow:
        case Output::return_flow: return joined({x.state(4), x.state(6)}, pressures_and_port);
        case Output::spool_position: return {x.state(4)};
        case Output::flapper_position:
        case Output::armature_angle: return {x.state(0)};
        case Output::left_control_pressure: return {x.state(2)};
        case Output::right_control_pressure: return {x.state(3)};
        case Output::saturated: return {x.state(0), x.state(4)};
        case Output::beyond_tables:
        case Output::count: break;
        }
      return joined(x.all(Role::state), x.all(Role::input));
    }
  } // namespace

  std::string model_description(const Layout &layout, const ModelDescriptionInfo &info)
  {
    const Indices x{layout};
    std::ostringstream s;
    s << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<fmiModelDescription fmiVersion=\"2.0\" modelName=\"servodrift_valve\" guid=\"" << info.guid << "\"\n"
      << "  description=\"" << escaped(info.description) << "\"\n"
      << "  version=\"" << escaped(info.version) << "\" generationTool=\"" << escaped(info.generation_tool)
      << "\" generationDateAndTime=\"" << info.generated_at << "\"\n"
      << "  variableNamingConvention=\"flat\" numberOfEventIndicators=\"0\">\n";
    const char *common = "modelIdentifier=\"servodrift_valve\" canGetAndSetFMUstate=\"true\" "
                         "canSerializeFMUstate=\"true\" canNotUseMemoryManagementFunctions=\"true\"";
    s << "  <ModelExchange " << common << " completedIntegratorStepNotNeeded=\"true\"/>\n"
      << "  <CoSimulation " << common << " canHandleVariableCommunicationStepSize=\"true\"/>\n";

    s << "  <UnitDefinitions>\n";
    for (const auto &u : unit_definitions())
      {
        s << "    <Unit name=\"" << u.name << "\"><BaseUnit";
        const std::pair<const char *, int> exponents[] = {{"kg", u.kg}, {"m", u.m}, {"s", u.s},
                                                          {"A", u.A},   {"K", u.K}, {"rad", u.rad}};
        for (const auto &[name, e] : exponents)
          if (e != 0)
            s << " " << name << "=\"" << e << "\"";
        s << "/>";
        if (!u.display_unit.empty())
          s << "<DisplayUnit name=\"" << u.display_unit << "\" offset=\"" << number(u.display_offset) << "\"/>";
        s << "</Unit>\n";
      }
    s << "  </UnitDefinitions>\n";

    s << "  <LogCategories>\n"
      << "    <Category name=\"logStatusWarning\" description=\"a warning: the FMU goes on (a temperature held at "
         "a table end, tables made with other parameters)\"/>\n"
      << "    <Category name=\"logStatusError\" description=\"an error: the call returned fmi2Error\"/>\n"
      << "    <Category name=\"logInfo\" description=\"notes, with debug logging on\"/>\n"
      << "  </LogCategories>\n";
    s << "  <DefaultExperiment startTime=\"0\" stopTime=\"" << number(info.stop_time) << "\" tolerance=\""
      << number(info.tolerance) << "\"/>\n";

    s << "  <ModelVariables>\n";
    for (std::size_t k = 0; k < layout.variables.size(); ++k)
      {
        const Variable &v = layout.variables[k];
        s << "    <!-- index " << k + 1 << " -->\n"
          << "    <ScalarVariable name=\"" << escaped(v.name) << "\" valueReference=\"" << k << "\" description=\""
          << escaped(v.description) << "\" causality=\"" << causality(v.role) << "\" variability=\""
          << (v.role == Role::parameter ? "fixed" : "continuous") << "\"";
        if (v.role == Role::parameter)
          s << " initial=\"exact\"";
        else if (v.role != Role::input)
          s << " initial=\"calculated\"";
        s << ">\n      ";
        if (v.boolean)
          s << "<Boolean start=\"" << (v.start && *v.start != 0 ? "true" : "false") << "\"/>\n";
        else
          {
            s << "<Real";
            if (!v.unit.empty())
              s << " unit=\"" << v.unit << "\"";
            if (!v.display_unit.empty())
              s << " displayUnit=\"" << v.display_unit << "\"";
            if (v.min)
              s << " min=\"" << number(*v.min) << "\"";
            if (v.max)
              s << " max=\"" << number(*v.max) << "\"";
            if (v.role == Role::derivative)
              s << " derivative=\"" << x.state(v.index) << "\"";
            if (v.start && (v.role == Role::input || v.role == Role::parameter))
              s << " start=\"" << number(*v.start) << "\"";
            s << "/>\n";
          }
        s << "    </ScalarVariable>\n";
      }
    s << "  </ModelVariables>\n";

    // ModelStructure: what each unknown depends on (model.md E29-E37)
    const auto unknown = [&s](std::size_t index, const std::vector<std::size_t> &dependencies) {
      s << "      <Unknown index=\"" << index << "\" dependencies=\"" << list(dependencies) << "\"/>\n";
    };
    const std::vector<std::size_t> states_and_inputs = joined(x.all(Role::state), x.all(Role::input));
    const std::vector<std::size_t> knowns_at_start = joined(x.all(Role::input), x.all(Role::parameter));
    s << "  <ModelStructure>\n    <Outputs>\n";
    for (std::size_t o = 0; o < static_cast<std::size_t>(Output::count); ++o)
      unknown(x.of(Role::output, o), output_dependencies(x, static_cast<Output>(o)));
    s << "    </Outputs>\n    <Derivatives>\n";
    for (std::size_t k = 0; k < layout.states; ++k)
      {
        // E29, E35: dtheta/dt and dx_v/dt are states themselves
        if (k == 0 || k == 4)
          unknown(x.of(Role::derivative, k), {x.state(k + 1)});
        else
          unknown(x.of(Role::derivative, k), states_and_inputs);
      }
    s << "    </Derivatives>\n    <InitialUnknowns>\n";
    std::vector<std::size_t> initial = joined(joined(x.all(Role::output), x.all(Role::state)), x.all(Role::derivative));
    for (std::size_t index : initial)
      unknown(index, knowns_at_start);
    s << "    </InitialUnknowns>\n  </ModelStructure>\n</fmiModelDescription>\n";
    return s.str();
  }
} // namespace servodrift::fmu
