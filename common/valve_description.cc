#include "common/valve_description.h"

#include "common/error.h"
#include "common/provenance.h"
#include "common/thermal_laws.h"
#include "common/units.h"

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <regex>
#include <sstream>
#include <tuple>

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
      SweepParameters::declare_parameters(prm);
      DynamicsParameters::declare_parameters(prm);
      FitParameters::declare_parameters(prm);
      OutputParameters::declare_parameters(prm);
    }

    void parse_all(ParameterHandler &prm, ValveDescription &v)
    {
      v.operating.parse_parameters(prm);
      v.torque_motor.parse_parameters(prm);
      v.expansion.parse_parameters(prm);
      v.spring_tube.parse_parameters(prm);
      v.armature.parse_parameters(prm);
      v.pilot.parse_parameters(prm);
      v.spool.parse_parameters(prm);
      v.fluid.parse_parameters(prm);
      v.flow_solver.parse_parameters(prm);
      v.offsets.parse_parameters(prm);
      v.sweeps.parse_parameters(prm);
      v.dynamics.parse_parameters(prm);
      v.fits.parse_parameters(prm);
      v.output.parse_parameters(prm);
    }

    /// deal.II's messages span several indented lines; ours are one line.
    std::string one_line(const std::string &text)
    {
      std::string out;
      bool space = false;
      for (char c : text)
        if (std::isspace(static_cast<unsigned char>(c)))
          space = !out.empty();
        else
          {
            if (space)
              out += ' ';
            out += c;
            space = false;
          }
      return out;
    }

    std::string info_of(const dealii::ExceptionBase &e)
    {
      std::ostringstream s;
      e.print_info(s);
      return one_line(s.str());
    }

    /// The subsection path ("A/B") open at a given line of a PRM file.
    std::string subsection_at_line(const std::string &file, int line_number)
    {
      std::ifstream in(file);
      std::vector<std::string> path;
      std::string line;
      for (int k = 1; k < line_number && std::getline(in, line); ++k)
        {
          line = one_line(line.substr(0, line.find('#')));
          if (line.rfind("subsection ", 0) == 0)
            path.push_back(line.substr(11));
          else if (line == "end" && !path.empty())
            path.pop_back();
        }
      std::string s;
      for (const auto &p : path)
        s += p + "/";
      return s;
    }

    /// Turns a deal.II parse error of `file' into one line naming file, line, entry and range.
    std::string describe_parse_error(const std::string &file, const dealii::ExceptionBase &e)
    {
      const std::string info = info_of(e);
      static const std::regex invalid(
        R"(Line <(\d+)> of file <[^>]*>: The entry value ?(.*?) for the entry named (.*) does not match the given pattern: (.*))");
      static const std::regex located(R"(Line <(\d+)> of file <[^>]*>:? ?(.*))");
      std::smatch m;
      if (std::regex_match(info, m, invalid))
        {
          const int line = std::stoi(m[1]);
          return file + ":" + m[1].str() + ": `" + subsection_at_line(file, line) + m[3].str() + "' = " +
                 m[2].str() + " is not allowed; allowed: " + m[4].str();
        }
      if (std::regex_match(info, m, located))
        {
          const std::string path = subsection_at_line(file, std::stoi(m[1]));
          return file + ":" + m[1].str() + ": " + m[2].str() +
                 (path.empty() ? std::string(" (at top level)") : " (in subsection `" + path.substr(0, path.size() - 1) + "')") +
                 "; `servodrift params' lists every entry";
        }
      return file + ": " + info;
    }

    /// Sets every entry of a JSON object tree: nested objects are subsections, a leaf (or an
    /// object with a "value" member, as `servodrift params --format json' writes) is an entry.
    void set_json_entries(ParameterHandler &prm, const boost::property_tree::ptree &tree, const std::string &file,
                          const std::string &path)
    {
      for (const auto &child : tree)
        {
          const std::string &key = child.first;
          const auto &node = child.second;
          const auto value = node.get_child_optional("value");
          if (node.empty() || value)
            {
              const std::string text = one_line(value ? value->data() : node.data());
              try
                {
                  prm.set(key, text);
                }
              catch (const dealii::ExceptionBase &e)
                {
                  static const std::regex mismatch(R"(The string <(.*)> does not match the given pattern <(.*)>\.)");
                  std::smatch m;
                  const std::string info = info_of(e);
                  if (std::regex_match(info, m, mismatch))
                    throw InputError(file + ": `" + path + key + "' = " + text + " is not allowed; allowed: " + m[2].str());
                  throw InputError(file + ": no entry `" + path + key + "' (`servodrift params' lists every entry)");
                }
            }
          else
            {
              if (!prm.subsection_path_exists({key}))
                throw InputError(file + ": no subsection `" + path + key + "' (`servodrift params' lists every entry)");
              prm.enter_subsection(key);
              set_json_entries(prm, node, file, path + key + "/");
              prm.leave_subsection();
            }
        }
    }

    void read_json_file(ParameterHandler &prm, const std::string &file)
    {
      boost::property_tree::ptree tree;
      std::ifstream in(file);
      boost::property_tree::read_json(in, tree);
      set_json_entries(prm, tree, file, "");
    }

    void read_input_file(ParameterHandler &prm, const std::string &file)
    {
      {
        std::ifstream probe(file);
        if (!probe)
          throw InputError(file + ": cannot open the parameter file (does it exist and is it readable?)");
      }
      const auto dot = file.rfind('.');
      const std::string extension = dot == std::string::npos ? "" : file.substr(dot);
      try
        {
          if (extension == ".prm")
            prm.parse_input(file);
          else if (extension == ".json")
            read_json_file(prm, file);
          else
            throw InputError(file + ": unknown parameter file format `" + extension +
                             "' (use a .prm or a .json file)");
        }
      catch (const InputError &)
        {
          throw;
        }
      catch (const dealii::ExceptionBase &e)
        {
          throw InputError(describe_parse_error(file, e));
        }
      catch (const boost::property_tree::json_parser_error &e)
        {
          throw InputError(file + ":" + std::to_string(e.line()) + ": not valid JSON: " + e.message());
        }
      catch (const std::exception &e)
        {
          throw InputError(file + ": " + one_line(e.what()));
        }
    }

    /// Applies one "Subsection/Key=value" override.
    void apply_override(ParameterHandler &prm, const std::string &override_text)
    {
      const std::string where = "--set \"" + override_text + "\"";
      const auto eq = override_text.find('=');
      if (eq == std::string::npos)
        throw InputError(where + ": expected \"Subsection/Key=value\"");
      std::string path = override_text.substr(0, eq);
      const std::string value = one_line(override_text.substr(eq + 1));
      std::vector<std::string> sections;
      for (std::size_t slash; (slash = path.find('/')) != std::string::npos; path = path.substr(slash + 1))
        sections.push_back(one_line(path.substr(0, slash)));
      const std::string key = one_line(path);
      if (sections.empty())
        throw InputError(where + ": expected \"Subsection/Key=value\"; every entry lives in a subsection");
      if (!prm.subsection_path_exists(sections))
        throw InputError(where + ": no subsection `" + sections.front() +
                         "' (`servodrift params' lists every entry)");
      for (const auto &s : sections)
        prm.enter_subsection(s);
      try
        {
          prm.set(key, value);
        }
      catch (const dealii::ExceptionBase &e)
        {
          for (std::size_t k = 0; k < sections.size(); ++k)
            prm.leave_subsection();
          const std::string info = info_of(e);
          static const std::regex mismatch(R"(The string <(.*)> does not match the given pattern <(.*)>\.)");
          std::smatch m;
          if (std::regex_match(info, m, mismatch))
            throw InputError(where + ": `" + value + "' is not allowed; allowed: " + m[2].str());
          throw InputError(where + ": no entry `" + key + "' in subsection `" + sections.back() +
                           "' (`servodrift params' lists every entry)");
        }
      for (std::size_t k = 0; k < sections.size(); ++k)
        prm.leave_subsection();
    }

    void fill(ParameterHandler &prm, const std::string &input_file, const std::vector<std::string> &overrides)
    {
      declare_all(prm);
      if (!input_file.empty())
        read_input_file(prm, input_file);
      for (const auto &o : overrides)
        apply_override(prm, o);
    }

    /// The values as used, without the Output subsection, which changes no number.
    std::string hashed_text(const ParameterHandler &prm)
    {
      std::ostringstream s;
      prm.print_parameters(s, ParameterHandler::ShortPRM);
      std::istringstream in(s.str());
      std::string line, out;
      bool in_output = false;
      while (std::getline(in, line))
        {
          const std::string t = one_line(line);
          if (t == std::string("subsection ") + OutputParameters::subsection)
            in_output = true;
          else if (in_output && t == "end" && line.find_first_not_of(' ') == 0)
            in_output = false;
          else if (!in_output)
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
                  doc = one_line(doc.substr(0, open));
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
    parse_all(prm, v);
    v.source = input_file.empty() ? "built-in RV-1" : input_file;
    std::ostringstream s;
    prm.print_parameters(s, style(ParameterHandler::PRM));
    v.parameter_file = s.str();
    v.parameters_sha256 = sha256_hex(hashed_text(prm));
    validate(v);
    return v;
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
            break;
          }
      }
    return s.str();
  }

  // ---- validation ----------------------------------------------------------------------------
  namespace
  {
    [[noreturn]] void refuse(const std::string &entry, const std::string &what)
    {
      throw InputError("`" + entry + "' " + what);
    }

    void require_increasing(const std::vector<double> &list, const std::string &entry, double scale = 1.0)
    {
      for (std::size_t k = 1; k < list.size(); ++k)
        if (!(list[k] > list[k - 1]))
          refuse(entry, "must be strictly increasing, but " + format_number(list[k - 1] / scale) +
                          " is followed by " + format_number(list[k] / scale));
    }
  } // namespace

  void validate_dynamics(const ValveDescription &v)
  {
    const auto &d = v.dynamics;
    const auto &op = v.operating;
    const auto &sw = v.sweeps;
    if (!(d.minimum_frequency < d.maximum_frequency))
      refuse("Dynamics/Minimum frequency", "= " + format_number(d.minimum_frequency) +
                                             " Hz must be below `Dynamics/Maximum frequency' = " +
                                             format_number(d.maximum_frequency) + " Hz");
    require_increasing(d.sine_frequencies, "Dynamics/Sine frequencies");
    require_increasing(d.sine_amplitudes, "Dynamics/Sine amplitudes");
    require_increasing(d.reading_times, "Dynamics/Reading times");
    const auto &tm = v.torque_motor;
    if (tm.voltage_drive && !(tm.coil_resistance > 0 && tm.coil_inductance > 0))
      refuse("Torque motor/Coil inductance", "and `Torque motor/Coil resistance' must be > 0 under voltage drive "
                                             "(`Torque motor/Coil drive' = voltage)");

    // Every current the analyses command must lie in the torque table: bias -+ the largest sine
    // amplitude, the small step, 0 and the rated current. Under voltage drive the coil current is a
    // state: a cold coil draws R_c(T0)/R_c(T) of the command, and near the armature's resonance the
    // back-EMF lets it overshoot by some 10 %, so the table must reach 1.25 times that.
    double ratio = 1;
    if (tm.voltage_drive)
      {
        for (double T : sw.drift_temperatures)
          ratio = std::max(ratio, laws::coil_resistance(tm, op.reference_temperature) / laws::coil_resistance(tm, T));
        ratio *= 1.25;
      }
    const double rated = op.rated_current, bias = d.bias * rated;
    const double amplitude = std::max(d.sine_amplitudes.back(), d.sine_check_amplitude) * rated;
    const double lowest = std::min({0.0, bias - amplitude}) * ratio;
    const double highest = std::max({rated, bias + amplitude, bias + d.small_step * rated}) * ratio;
    const auto &currents = sw.motor_currents;
    if (lowest < currents.front() || highest > currents.back())
      refuse("Dynamics/Sine amplitudes",
             "with `Dynamics/Bias' = " + format_number(d.bias) + " command currents from " + format_number(lowest) +
               " to " + format_number(highest) + " A" +
               (tm.voltage_drive ? " (under voltage drive: a cold coil's current with 25 % for its overshoot)" : "") +
               ", beyond the torque table's `Sweeps/Motor currents' [" + format_number(currents.front()) + ", " +
               format_number(currents.back()) + "] A; lower the amplitudes or the bias, or extend the currents");
    // The flapper may reach a nozzle in a transient (it saturates there): the torque table must
    // reach the nozzle contacts, theta = (+-x0(T) + x_n)/r.
    double contact = 0;
    for (double T : sw.table_temperatures)
      {
        const auto g = laws::pilot_stage_geometry(v.pilot, v.armature, v.expansion, T, op.reference_temperature);
        contact = std::max(contact, (g.null_gap + std::abs(v.offsets.hydraulic_null)) / v.armature.pivot_to_nozzle_distance +
                                      std::abs(v.offsets.magnetic_null));
      }
    if (-sw.motor_angles.front() < contact || sw.motor_angles.back() < contact)
      refuse("Sweeps/Motor angles", "must reach the nozzle contacts at +-" + format_number(1.001 * contact / units::degree) +
                                      " deg for the dynamics, where the flapper may hit a nozzle in a transient "
                                      "(or set `Dynamics/Enabled' = false)");
  }

  void validate(const ValveDescription &v)
  {
    const auto &op = v.operating;
    if (!(op.return_pressure < op.supply_pressure))
      refuse("Operating conditions/Return pressure",
             "= " + format_number(op.return_pressure) + " Pa must be below the supply pressure " +
               format_number(op.supply_pressure) + " Pa");

    // Sweep lists
    const auto &sw = v.sweeps;
    require_increasing(sw.table_temperatures, "Sweeps/Table temperatures");
    require_increasing(sw.motor_angles, "Sweeps/Motor angles", units::degree);
    require_increasing(sw.motor_currents, "Sweeps/Motor currents");
    require_increasing(sw.pressure_fractions, "Sweeps/Pressure fractions");
    require_increasing(sw.gap_fractions, "Sweeps/Gap fractions");
    require_increasing(sw.field_orifice_pressure_fractions, "Sweeps/Field orifice pressure fractions");
    require_increasing(sw.field_gap_fractions, "Sweeps/Field gap fractions");
    require_increasing(sw.field_nozzle_pressure_fractions, "Sweeps/Field nozzle pressure fractions");
    for (const auto &[list, entry] : {std::make_pair(&sw.field_orifice_pressure_fractions, "Sweeps/Field orifice pressure fractions"),
                                      std::make_pair(&sw.field_gap_fractions, "Sweeps/Field gap fractions"),
                                      std::make_pair(&sw.field_nozzle_pressure_fractions, "Sweeps/Field nozzle pressure fractions")})
      if (!(list->front() > 0))
        refuse(entry, "starts with " + format_number(list->front()) +
                        ": the field level computes only flowing cases (> 0; the table adds the zero row itself)");
    require_increasing(sw.drift_temperatures, "Sweeps/Drift temperatures");
    require_increasing(sw.deviation_angles, "Sweeps/Deviation angles", units::degree);

    // Temperatures inside the oil law's window (E16 is singular at T = -C)
    const auto &fl = v.fluid;
    if (!(fl.minimum_temperature < fl.maximum_temperature))
      refuse("Fluid/Minimum temperature", "= " + format_number(fl.minimum_temperature) +
                                            " degC must be below `Fluid/Maximum temperature' = " +
                                            format_number(fl.maximum_temperature) + " degC");
    if (fl.viscosity_law == FluidParameters::ViscosityLaw::vogel && !(fl.minimum_temperature > -fl.vogel_c))
      refuse("Fluid/Minimum temperature", "= " + format_number(fl.minimum_temperature) +
                                            " degC must be above -`Fluid/Vogel C' = " +
                                            format_number(-fl.vogel_c) + " degC, where E16 is singular");
    auto check_window = [&](const std::vector<double> &list, const std::string &entry) {
      for (double T : list)
        if (!(T >= fl.minimum_temperature && T <= fl.maximum_temperature))
          refuse(entry, "contains " + format_number(T) + " degC, outside the oil viscosity law's window [" +
                          format_number(fl.minimum_temperature) + ", " + format_number(fl.maximum_temperature) +
                          "] degC (`Fluid/Minimum temperature', `Fluid/Maximum temperature')");
    };
    check_window(sw.table_temperatures, "Sweeps/Table temperatures");
    check_window(sw.drift_temperatures, "Sweeps/Drift temperatures");
    check_window({op.reference_temperature}, "Operating conditions/Reference temperature");
    const double T_lo = sw.table_temperatures.front(), T_hi = sw.table_temperatures.back();
    auto check_in_tables = [&](double T, const std::string &entry) {
      if (!(T >= T_lo && T <= T_hi))
        refuse(entry, "contains " + format_number(T) + " degC, outside the table temperatures [" +
                        format_number(T_lo) + ", " + format_number(T_hi) + "] degC (`Sweeps/Table temperatures')");
    };
    for (double T : sw.drift_temperatures)
      check_in_tables(T, "Sweeps/Drift temperatures");
    check_in_tables(op.reference_temperature, "Operating conditions/Reference temperature");

    // Torque motor: gaps open at every temperature and every tabulated angle (E2, E6, E7)
    const auto &tm = v.torque_motor;
    if (!(tm.pivot_to_pole_distance > 0 && tm.pole_face_width > 0 && tm.pole_face_length > 0 &&
          tm.magnet_length > 0 && tm.magnet_width > 0 && tm.magnet_depth > 0))
      refuse("Torque motor", "dimensions (pivot distance, pole face, magnet) must all be > 0");
    double max_angle = 0;
    for (double a : sw.motor_angles)
      max_angle = std::max(max_angle, std::abs(a));
    for (double T : sw.table_temperatures)
      {
        const auto g = laws::torque_motor_geometry(tm, v.expansion, T, op.reference_temperature);
        if (!(g.lower_gap > 0))
          refuse("Torque motor/Armature height",
                 "gives a closed lower gap g_12 = H_a - H_ar/2 - H_c = " + format_number(g.lower_gap) + " m at " +
                   format_number(T) + " degC (E6); it must be > 0");
        if (!(g.upper_gap > 0))
          refuse("Torque motor/Armature height",
                 "gives a closed upper gap g_34 = H_c' + H_m - h_p - H_a - H_ar/2 = " + format_number(g.upper_gap) +
                   " m at " + format_number(T) + " degC (E7); it must be > 0");
        // the armature's tip, at the outer edge of the pole faces (or its own end), must not touch
        const double tip = std::max(g.pivot_to_pole_distance + 0.5 * g.pole_face_length,
                                    laws::expanded(tm.armature_length / 2, v.expansion.armature, T, op.reference_temperature));
        const double closing = tip * max_angle;
        const double gap = std::min(g.lower_gap, g.upper_gap);
        if (!(closing < 0.95 * gap))
          refuse("Sweeps/Motor angles",
                 "reach " + format_number(max_angle / units::degree) + " deg, where the armature tip moves " +
                   format_number(closing) + " m of a " + format_number(gap) + " m gap at " + format_number(T) +
                   " degC; keep |angle| below " + format_number(0.95 * gap / tip / units::degree) + " deg");
      }
    if (!(sw.motor_angles.front() <= -0.1 * units::degree && sw.motor_angles.back() >= 0.1 * units::degree))
      refuse("Sweeps/Motor angles", "must cover -0.1..0.1 deg, where the secant K_m is evaluated (C1)");
    const double i_rated = op.rated_current;
    if (!(sw.motor_currents.front() <= -i_rated && sw.motor_currents.back() >= i_rated))
      refuse("Sweeps/Motor currents", "must cover -rated..rated current, +-" + format_number(i_rated) + " A");

    // Field model of the torque motor (meshes/torque_motor.geo): parts must not overlap
    if (tm.model_level == "field")
      {
        const std::string field = " (field model, meshes/torque_motor.geo)";
        const double pole_tip_start = tm.pivot_to_pole_distance - 0.5 * tm.pole_face_length;
        if (!(tm.coil_height > 0))
          refuse("Torque motor/Coil height", "= " + format_number(tm.coil_height) + " m must be > 0: the coil's current "
                                             "density region needs an area" + field);
        if (!(tm.coil_clearance > 0))
          refuse("Torque motor/Coil clearance", "must be > 0: the coil may not touch the moving armature" + field);
        if (!(tm.coil_inner_position < tm.coil_outer_position))
          refuse("Torque motor/Coil inner position", "= " + format_number(tm.coil_inner_position) +
                                                       " m must be below `Torque motor/Coil outer position' = " +
                                                       format_number(tm.coil_outer_position) + " m" + field);
        if (!(tm.coil_outer_position < pole_tip_start))
          refuse("Torque motor/Coil outer position", "= " + format_number(tm.coil_outer_position) +
                                                       " m reaches the pole tips, which start at " +
                                                       format_number(pole_tip_start) + " m" + field);
        const double upper_plate = tm.upper_pole_thickness + tm.magnet_length - tm.armature_height;
        const double lower_plate = tm.upper_pole_thickness - tm.armature_height;
        const double coil_reach = 0.5 * tm.armature_thickness + tm.coil_clearance + tm.coil_height;
        if (!(coil_reach < upper_plate && -coil_reach > lower_plate))
          refuse("Torque motor/Coil height", "= " + format_number(tm.coil_height) +
                                               " m makes a coil region reach a pole plate" + field);
        if (!(tm.field_magnet_clearance > 0.5 * tm.armature_length - tm.pivot_to_pole_distance - 0.5 * tm.pole_face_length))
          refuse("Torque motor/Field magnet clearance", "puts the magnet blocks over the armature's tip" + field);
        if (!(tm.field_magnet_width > 0))
          refuse("Torque motor/Field magnet width", "must be > 0" + field);
        const double half_size = std::max(tm.pivot_to_pole_distance + 0.5 * tm.pole_face_length + tm.field_magnet_clearance +
                                            tm.field_magnet_width,
                                          tm.armature_height + tm.upper_plate_thickness);
        if (!(tm.air_boundary_radius > 1.5 * half_size))
          refuse("Torque motor/Air boundary radius", "= " + format_number(tm.air_boundary_radius) +
                                                       " m must enclose the motor with room, at least " +
                                                       format_number(1.5 * half_size) + " m" + field);
      }

    // Spring tube
    const auto &st = v.spring_tube;
    if (!(st.outer_diameter > 0 && st.length > 0))
      refuse("Spring tube/Outer diameter", "and `Spring tube/Length' must be > 0");
    if (!(st.inner_diameter < st.outer_diameter))
      refuse("Spring tube/Inner diameter", "= " + format_number(st.inner_diameter) +
                                             " m must be below the outer diameter " +
                                             format_number(st.outer_diameter) + " m (wall thickness > 0)");
    if (st.model_level == "field")
      {
        const std::string field = " for the field level (`Spring tube/Model level = field')";
        if (!(st.inner_diameter > 0))
          refuse("Spring tube/Inner diameter", "= " + format_number(st.inner_diameter) +
                                                 " m must be > 0" + field +
                                                 ": the n = 1 axisymmetric model needs a bore");
        if (!(st.poisson_ratio < 0.5))
          refuse("Spring tube/Poisson ratio", "= " + format_number(st.poisson_ratio) + " must be below 0.5" + field +
                                                " (Lame's lambda is infinite for an incompressible solid)");
        // a flange or collar of height > 0 must stand out of the tube, or there is nothing to mesh
        for (const auto &[part, diameter, height] :
             {std::tuple{"Base flange", st.base_flange_diameter, st.base_flange_height},
              std::tuple{"Top collar", st.top_collar_diameter, st.top_collar_height}})
          if (height > 0 && !(diameter > st.outer_diameter))
            refuse(std::string("Spring tube/") + part + " diameter",
                   "= " + format_number(diameter) + " m must exceed the outer diameter " +
                     format_number(st.outer_diameter) + " m when its height is > 0" + field +
                     " (set the height to 0 for none)");
        const double radial_size = 0.5 * (st.outer_diameter - st.inner_diameter) /
                                   (st.field_wall_layers * st.field_mesh_resolution);
        for (const auto &[entry, height] : {std::pair{"Base flange height", st.base_flange_height},
                                            std::pair{"Top collar height", st.top_collar_height}})
          if (height > 0 && !(height > 0.05 * radial_size))
            refuse(std::string("Spring tube/") + entry,
                   "= " + format_number(height) + " m cannot be meshed: a height above 0 must be at least " +
                     format_number(0.05 * radial_size) + " m (1/20 of the wall's element size)" + field);
        if (st.field_wall_layers * st.field_mesh_resolution < 1)
          refuse("Spring tube/Field mesh resolution", "x `Field wall layers' must give at least one layer");
      }
    for (double T : sw.table_temperatures)
      if (!(laws::youngs_modulus(st, T) > 0))
        refuse("Spring tube/Modulus temperature coefficient", "makes E(T) <= 0 at " + format_number(T) + " degC (E12)");

    // Pilot stage
    const auto &ps = v.pilot;
    if (!(ps.fixed_orifice_diameter > 0 && ps.fixed_orifice_length > 0 && ps.nozzle_diameter > 0))
      refuse("Pilot stage", "orifice and nozzle dimensions must be > 0");
    if (!(ps.null_gap > 0))
      refuse("Pilot stage/Null gap", "= " + format_number(ps.null_gap) + " m must be > 0");
    if (!(ps.null_gap <= 0.25 * ps.nozzle_diameter))
      refuse("Pilot stage/Null gap", "= " + format_number(ps.null_gap) +
                                       " m must not exceed a quarter of the nozzle diameter, D_N/4 = " +
                                       format_number(0.25 * ps.nozzle_diameter) +
                                       " m, or the nozzle bore instead of the curtain throttles (E32)");
    if (!(ps.land_diameter > ps.nozzle_diameter))
      refuse("Pilot stage/Land diameter", "= " + format_number(ps.land_diameter) +
                                            " m must be above the nozzle diameter " +
                                            format_number(ps.nozzle_diameter) + " m (E22)");
    if (!(ps.nozzle_discharge_coefficient > 0))
      refuse("Pilot stage/Nozzle discharge coefficient", "must be > 0");
    for (double T : sw.table_temperatures)
      {
        const auto g = laws::pilot_stage_geometry(ps, v.armature, v.expansion, T, op.reference_temperature);
        if (!(g.null_gap > 0))
          refuse("Pilot stage/Nozzle seat span", "makes the null gap close at " + format_number(T) + " degC (2.3)");
      }
    if (!(v.armature.pivot_to_nozzle_distance > 0))
      refuse("Armature/Pivot to nozzle distance", "must be > 0");

    // Spool
    const auto &sp = v.spool;
    if (!(sp.control_diameter > 0 && sp.feedback_diameter > 0))
      refuse("Spool/Control diameter", "and `Spool/Feedback diameter' must be > 0");
    if (!(sp.overlap > 0))
      refuse("Spool/Overlap", "= " + format_number(sp.overlap) +
                                " m must be > 0: a critically lapped spool has no unique blocked-port steady "
                                "state in this model");
    if (!(sp.stroke_limit > sp.overlap))
      refuse("Spool/Stroke limit", "= " + format_number(sp.stroke_limit) + " m must exceed the overlap " +
                                     format_number(sp.overlap) + " m");

    // Parts of the dynamic model that the static model uses as well (E36 leakage) or that must be
    // physical whatever runs
    if (!(sp.radial_clearance > 0))
      refuse("Spool/Radial clearance", "= " + format_number(sp.radial_clearance) +
                                         " m must be > 0: the lap leakage sets the blocked brake port's pressure (E36)");
    if (!(v.armature.inertia > 0))
      refuse("Armature/Inertia", "= " + format_number(v.armature.inertia) + " kg*m^2 must be > 0 (E29)");
    if (!(sp.mass > 0))
      refuse("Spool/Mass", "= " + format_number(sp.mass) + " kg must be > 0 (E35)");
    if (!(sp.brake_volume > 0))
      refuse("Spool/Brake volume", "= " + format_number(sp.brake_volume) + " m^3 must be > 0 (E37)");
    if (!(sp.port_volume > 0))
      refuse("Spool/Port volume", "= " + format_number(sp.port_volume) + " m^3 must be > 0 (E37)");
    {
      const double swept = 0.25 * units::pi * sp.control_diameter * sp.control_diameter * sp.stroke_limit;
      if (!(ps.control_cavity_volume > swept))
        refuse("Pilot stage/Control cavity volume",
               "= " + format_number(ps.control_cavity_volume) + " m^3 must exceed the volume the spool end sweeps over "
                 "its stroke, A_v x stroke = " + format_number(swept) + " m^3 (E33: V_0 -+ A_v x_v > 0)");
    }
    if (!(fl.bulk_modulus > 0))
      refuse("Fluid/Bulk modulus", "= " + format_number(fl.bulk_modulus) + " Pa must be > 0 (2.8)");
    for (double T : sw.drift_temperatures)
      if (!(1 - fl.bulk_modulus_temperature_coefficient * (T - op.reference_temperature) > 0))
        refuse("Fluid/Bulk modulus temperature coefficient",
               "= " + format_number(fl.bulk_modulus_temperature_coefficient) + " 1/degC makes beta_e <= 0 at " +
                 format_number(T) + " degC (2.8); it must stay below " +
                 format_number(1 / (T - op.reference_temperature)) + " 1/degC");
    if (v.dynamics.enabled)
      validate_dynamics(v);

    // Offsets (C8): re-nulling with the hydraulic null removes a hydraulic-null deviation exactly
    if (v.offsets.deviation_target == OffsetParameters::Target::hydraulic_null &&
        v.offsets.nulling == OffsetParameters::Nulling::nulled_at_reference)
      refuse("Offsets/Deviation target", "= hydraulic-null with `Offsets/Nulling' = nulled-at-reference gives zero "
                                         "drift by construction (C8); use as-assembled or another target");
  }
} // namespace servodrift
