#include "common/valve_description.h"

#include "common/error.h"
#include "common/parameter_input.h"
#include "common/parameters/parameter_helpers.h"
#include "common/parameters/renamed_entries.h"
#include "common/provenance.h"

#include <deal.II/base/parameter_handler.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace servodrift
{
  namespace
  {
    using dealii::ParameterHandler;

    /// Parameter files list the entries in declaration order, which follows the model.
    ParameterHandler::OutputStyle style(ParameterHandler::OutputStyle format)
    {
      return static_cast<ParameterHandler::OutputStyle>(format | ParameterHandler::KeepDeclarationOrder);
    }

    void declare_all(ParameterHandler &prm)
    {
      OperatingConditions::declare_parameters(prm);
      TorqueMotorParameters::declare_parameters(prm);
      ThermalExpansion::declare_parameters(prm);
      SpringTubeParameters::declare_parameters(prm);
      ArmatureParameters::declare_parameters(prm);
      PilotStageParameters::declare_parameters(prm);
      SpoolParameters::declare_parameters(prm);
      FluidParameters::declare_parameters(prm);
      FlowSolverParameters::declare_parameters(prm);
      OffsetParameters::declare_parameters(prm);
      AsymmetryParameters::declare_parameters(prm);
      SweepParameters::declare_parameters(prm);
      DynamicsParameters::declare_parameters(prm);
      ToleranceParameters::declare_parameters(prm);
      FitParameters::declare_parameters(prm);
      OutputParameters::declare_parameters(prm);
    }

    void fill(ParameterHandler &prm, const std::string &input_file, const std::vector<std::string> &overrides)
    {
      declare_all(prm);
      read_parameters(prm, input_file, overrides);
    }

    /// The values as used, without the subsections that change no table: Output, and Tolerances (the
    /// tolerance study reads the tables of the valve as described; its settings are in parameters.prm).
    std::string hashed_text(const ParameterHandler &prm)
    {
      std::ostringstream s;
      prm.print_parameters(s, ParameterHandler::ShortPRM);
      std::istringstream in(s.str());
      std::string line, out;
      bool skipping = false;
      while (std::getline(in, line))
        {
          const std::string t = collapse_whitespace(line);
          if (t == std::string("subsection ") + OutputParameters::subsection ||
              t == std::string("subsection ") + ToleranceParameters::subsection)
            skipping = true;
          else if (skipping && t == "end" && line.find_first_not_of(' ') == 0)
            skipping = false;
          else if (!skipping)
            out += line + "\n";
        }
      return out;
    }

    // ---- markdown parameter reference ---------------------------------------------------------
    void markdown_rows(const boost::property_tree::ptree &tree, const std::string &path, std::ostream &out)
    {
      for (const auto &child : tree)
        {
          const auto &node = child.second;
          if (node.get_child_optional("value"))
            {
              std::string doc = node.get<std::string>("documentation", "");
              std::string unit;
              const auto open = doc.rfind('[');
              if (open != std::string::npos && doc.back() == ']')
                {
                  unit = doc.substr(open + 1, doc.size() - open - 2);
                  doc = collapse_whitespace(doc.substr(0, open));
                }
              std::string pattern = node.get<std::string>("pattern_description", "");
              std::replace(pattern.begin(), pattern.end(), '|', '/');
              out << "| `" << path << "` | `" << child.first << "` | `" << node.get<std::string>("default_value")
                  << "` | " << unit << " | " << pattern << " | " << doc << " |\n";
            }
          else
            markdown_rows(node, path.empty() ? child.first : path + "/" + child.first, out);
        }
    }

  } // namespace

  ValveDescription load_valve_description(const std::string &input_file, const std::vector<std::string> &overrides)
  {
    ParameterHandler prm;
    fill(prm, input_file, overrides);
    ValveDescription v;
    parameters::HandlerSource values(prm);
    parse_valve_description(values, v);
    v.source = input_file.empty() ? "built-in RV-1" : input_file;
    std::ostringstream s;
    prm.print_parameters(s, style(ParameterHandler::PRM));
    v.parameter_file = s.str();
    v.parameters_sha256 = sha256_hex(hashed_text(prm));
    validate(v);
    return v;
  }

  ValveDescriptionVariants::ValveDescriptionVariants(const std::string &input_file,
                                                     const std::vector<std::string> &overrides)
    : prm(std::make_unique<ParameterHandler>())
    , source(input_file.empty() ? "built-in RV-1" : input_file)
  {
    fill(*prm, input_file, overrides);
  }

  ValveDescriptionVariants::~ValveDescriptionVariants() = default;

  ValveDescription ValveDescriptionVariants::with(const std::vector<std::pair<std::string, std::string>> &entries)
  {
    for (const auto &[path, value] : entries)
      {
        std::vector<std::string> parts;
        std::stringstream items(path);
        for (std::string part; std::getline(items, part, '/');)
          parts.push_back(part);
        for (std::size_t k = 0; k + 1 < parts.size(); ++k)
          prm->enter_subsection(parts[k]);
        try
          {
            prm->set(parts.back(), value);
          }
        catch (const dealii::ExceptionBase &)
          {
            for (std::size_t k = 0; k + 1 < parts.size(); ++k)
              prm->leave_subsection();
            throw InputError("`" + shown_input(path) + "' = " + shown_input(value) + " is not allowed");
          }
        for (std::size_t k = 0; k + 1 < parts.size(); ++k)
          prm->leave_subsection();
      }
    ValveDescription v;
    parameters::HandlerSource values(*prm);
    parse_valve_description(values, v);
    v.source = source;
    validate(v);
    return v;
  }

  NumericEntry numeric_entry(const std::string &input_file, const std::vector<std::string> &overrides,
                             const std::string &path)
  {
    ParameterHandler prm;
    fill(prm, input_file, overrides);
    std::ostringstream json;
    prm.print_parameters(json, style(ParameterHandler::JSON));
    std::istringstream in(json.str());
    boost::property_tree::ptree tree;
    boost::property_tree::read_json(in, tree);
    const boost::property_tree::ptree *node = &tree;
    std::stringstream parts(path);
    for (std::string part; std::getline(parts, part, '/');)
      {
        const auto child = node->find(part);
        if (child == node->not_found())
          throw InputError("`" + shown_input(path) + "' is not an entry of the valve description (`servodrift params' "
                                                     "lists every entry)");
        node = &child->second;
      }
    if (!node->get_child_optional("value"))
      throw InputError("`" + shown_input(path) + "' is a subsection, not an entry");
    // "[Double -0.0001...0.0001 (inclusive)]" or "[Integer 1...10000000 (inclusive)]"
    const std::string pattern = node->get<std::string>("pattern_description", "");
    double lower = 0, upper = 0;
    const std::size_t space = pattern.find(' '), dots = pattern.find("...");
    const std::string kind = pattern.substr(1, space == std::string::npos ? 0 : space - 1);
    if ((kind != "Double" && kind != "Integer") || dots == std::string::npos)
      throw InputError("`" + shown_input(path) + "' is not a number (allowed: " + pattern + ")");
    lower = std::strtod(pattern.c_str() + space + 1, nullptr); // "-10." would take a dot of "..."
    upper = std::strtod(pattern.c_str() + dots + 3, nullptr);
    NumericEntry e{path, std::stod(node->get<std::string>("value")), lower, upper, ""};
    const std::string doc = node->get<std::string>("documentation", "");
    const auto open = doc.rfind('[');
    if (open != std::string::npos && doc.back() == ']')
      e.unit = doc.substr(open + 1, doc.size() - open - 2);
    return e;
  }

  std::string print_parameters(const std::string &input_file, const std::vector<std::string> &overrides,
                               ParameterFormat format)
  {
    ParameterHandler prm;
    fill(prm, input_file, overrides);
    std::ostringstream s;
    switch (format)
      {
        case ParameterFormat::prm:
          prm.print_parameters(s, style(ParameterHandler::PRM));
          break;
        case ParameterFormat::json:
          prm.print_parameters(s, style(ParameterHandler::JSON));
          break;
        case ParameterFormat::markdown:
          {
            std::ostringstream json;
            prm.print_parameters(json, style(ParameterHandler::JSON));
            std::istringstream in(json.str());
            boost::property_tree::ptree tree;
            boost::property_tree::read_json(in, tree);
            s << "# servodrift parameter reference\n\n"
              << "Generated by `servodrift params --format markdown` from the declarations in "
                 "`common/parameters/`; do not edit. Defaults are the built-in valve RV-1. Units are SI, "
                 "temperatures in degC, typed angles in degree.\n\n"
              << "| subsection | entry | default (RV-1) | unit | allowed | meaning |\n"
              << "|---|---|---|---|---|---|\n";
            markdown_rows(tree, "", s);
            s << "\n## Moved entries\n\n"
              << "Read under their old paths too, from a parameter file, a JSON file, `--set` or `--free`, "
                 "with a one-line deprecation warning (`common/parameters/renamed_entries.cc`).\n\n"
              << "| old path | now |\n|---|---|\n";
            for (const auto &entry : renamed_entries())
              s << "| `" << entry.old_path << "` | `" << entry.new_path << "` |\n";
            break;
          }
      }
    return s.str();
  }

} // namespace servodrift
