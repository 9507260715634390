#include "fmu/fmu_variables.h"

#include "common/output_files.h"
#include "common/units.h"
#include "system/valve_equations.h"

#include <algorithm>

namespace servodrift::fmu
{
  const std::vector<Parameter> &valve_parameters()
  {
    static const std::vector<Parameter> list = [] {
      std::vector<Parameter> p = {
          {"spring_tube_rest_angle", "rad", "theta_s: the spring tube's rest angle (Offsets, E39)",
           [](ValveDescription &v) -> double & { return v.offsets.spring_tube_rest_angle; }},
          {"magnetic_null", "rad", "theta_m: the torque motor's magnetic null (Offsets, E39)",
           [](ValveDescription &v) -> double & { return v.offsets.magnetic_null; }},
          {"hydraulic_null", "m",
           "x_n: the hydraulic null (Offsets, E39); recomputed at initialisation when the valve file says "
           "`Offsets/Nulling = nulled-at-reference'",
           [](ValveDescription &v) -> double & { return v.offsets.hydraulic_null; }},
          {"lower_gap_mismatch", "m", "torque motor: g_1 - g_2 at theta = 0 (Asymmetry, E2, E3)",
           [](ValveDescription &v) -> double & { return v.asymmetry.lower_gap_mismatch; }},
          {"left_magnet_remanence_deviation", "", "(B_r - nominal B_r)/nominal B_r of the left magnet (Asymmetry, E8)",
           [](ValveDescription &v) -> double & { return v.asymmetry.left_remanence; }},
          {"right_magnet_remanence_deviation", "",
           "(B_r - nominal B_r)/nominal B_r of the right magnet (Asymmetry, E8)",
           [](ValveDescription &v) -> double & { return v.asymmetry.right_remanence; }}};
      for (const bool left : {true, false})
        {
          const std::string side = left ? "left" : "right";
          const auto deviations = [left](ValveDescription &v) -> SideDeviations & {
            return left ? v.asymmetry.left : v.asymmetry.right;
          };
          p.push_back({side + "_orifice_diameter_deviation", "m",
                       "the " + side + " fixed orifice's diameter minus the nominal (Asymmetry, E31)",
                       [deviations](ValveDescription &v) -> double & { return deviations(v).orifice_diameter; }});
          p.push_back({side + "_nozzle_diameter_deviation", "m",
                       "the " + side + " nozzle's diameter minus the nominal (Asymmetry, E32, E23)",
                       [deviations](ValveDescription &v) -> double & { return deviations(v).nozzle_diameter; }});
          p.push_back({side + "_null_gap_deviation", "m",
                       "the " + side + " nozzle-flapper gap at x_f = 0 minus the nominal x0(T) (Asymmetry)",
                       [deviations](ValveDescription &v) -> double & { return deviations(v).null_gap; }});
          p.push_back(
              {side + "_orifice_discharge_factor", "",
               "the " + side + " fixed orifice's C_d over the table's (Asymmetry, E31)",
               [deviations](ValveDescription &v) -> double & { return deviations(v).orifice_discharge_factor; }});
          p.push_back(
              {side + "_nozzle_discharge_factor", "",
               "the " + side + " nozzle-flapper gap's C_d over the table's (Asymmetry, E32)",
               [deviations](ValveDescription &v) -> double & { return deviations(v).nozzle_discharge_factor; }});
        }
      return p;
    }();
    return list;
  }

  std::pair<double, double> table_temperature_range(const system::StageFunctions &f)
  {
    const std::vector<const GridFunction *> tables = {&f.torque, &f.stiffness, &f.orifice_conductance,
                                                      &f.nozzle_conductance};
    std::pair<double, double> range = {-1e300, 1e300};
    for (const GridFunction *t : tables)
      range = {std::max(range.first, t->axis(0).front()), std::min(range.second, t->axis(0).back())};
    return range;
  }

  unsigned int Layout::first(Role role) const
  {
    for (std::size_t k = 0; k < variables.size(); ++k)
      if (variables[k].role == role)
        return static_cast<unsigned int>(k);
    return static_cast<unsigned int>(variables.size());
  }

  Layout layout(const ValveDescription &valve, const system::StageFunctions &tables)
  {
    const auto [lowest_temperature, highest_temperature] = table_temperature_range(tables);
    const std::vector<double> &currents = tables.torque.axis(2);
    Layout l;
    l.voltage_drive = valve.torque_motor.voltage_drive;
    l.states = l.voltage_drive ? 8 : 7;
    auto &v = l.variables;

    // states of model.md 1.20 and their derivatives (system/valve_equations.h)
    struct StateText
    {
      const char *name, *unit, *rate_unit, *description;
    };
    const StateText states[] = {
        {"armature_angle_state", "rad", "rad/s", "theta: the armature's angle (E29)"},
        {"armature_angular_velocity_state", "rad/s", "rad/s2", "dtheta/dt (E29)"},
        {"left_control_pressure_state", "Pa", "Pa/s", "p_L, gauge: the left control cavity (E33)"},
        {"right_control_pressure_state", "Pa", "Pa/s", "p_R, gauge: the right control cavity (E33)"},
        {"spool_position_state", "m", "m/s", "x_v: the spool's displacement (E35)"},
        {"spool_velocity_state", "m/s", "m/s2", "dx_v/dt (E35)"},
        {"brake_pressure_state", "Pa", "Pa/s",
         "p_B, gauge: the valve's brake volume (E37); held at the port's pressure with an external brake port"},
        {"coil_current_state", "A", "A/s", "i: the coil current under voltage drive (coil circuit)"}};
    for (std::size_t k = 0; k < l.states; ++k)
      v.push_back({states[k].name, Role::state, k, false, states[k].unit, "", states[k].description, {}, {}, {}});
    for (std::size_t k = 0; k < l.states; ++k)
      v.push_back({std::string("der(") + states[k].name + ")", Role::derivative, k, false, states[k].rate_unit, "",
                   std::string("d/dt of ") + states[k].name, {}, {}, {}});

    const auto &op = valve.operating;
    const auto index = [](auto e) { return static_cast<std::size_t>(e); };
    using Bound = std::optional<double>;
    const auto input = [&](Input i, const char *name, const char *unit, const char *display_unit,
                           const std::string &description, double start, Bound min, Bound max) {
      v.push_back({name, Role::input, index(i), false, unit, display_unit, description, start, min, max});
    };
    if (l.voltage_drive)
      input(Input::coil, "coil_voltage", "V", "", "voltage across the coil (the valve file says voltage drive)", 0.0,
            {}, {});
    else
      input(Input::coil, "coil_current", "A", "",
            "control current through the coil (rated: " + format_cell(op.rated_current) +
              " A); min and max: the torque table's currents",
            0.0, currents.front(), currents.back());
    input(Input::supply_pressure, "supply_pressure", "Pa", "",
          "supply pressure p_s, gauge; the tables were made for the described one", op.supply_pressure, 0.0, {});
    input(Input::return_pressure, "return_pressure", "Pa", "", "return pressure p_r, gauge", op.return_pressure, 0.0,
          {});
    input(Input::oil_temperature, "oil_temperature", "K", "degC",
          "oil and valve temperature, uniform (the valve at thermal equilibrium); outside [min, max] the FMU warns "
          "and holds the end value",
          units::celsius_to_kelvin + op.reference_temperature, units::celsius_to_kelvin + lowest_temperature,
          units::celsius_to_kelvin + highest_temperature);
    input(Input::brake_port_pressure, "brake_port_pressure", "Pa", "",
          "pressure of the brake line at the valve's port, gauge: used when external_brake_port", 0.0, {}, {});

    const auto output = [&](Output o, const char *name, const char *unit, const std::string &description) {
      v.push_back({name, Role::output, index(o), false, unit, "", description, {}, {}, {}});
    };
    output(Output::brake_pressure, "brake_pressure", "Pa", "p_B, gauge: the regulated brake pressure");
    output(Output::brake_flow, "brake_flow", "m3/s",
           "flow out of the valve into the brake port (supply edge minus return edge, E36)");
    output(Output::spool_position, "spool_position", "m", "x_v, positive towards supply-to-brake");
    output(Output::flapper_position, "flapper_position", "m", "x_f = r theta - x_n at the nozzles (E30)");
    output(Output::armature_angle, "armature_angle", "rad", "theta (E29)");
    output(Output::left_control_pressure, "left_control_pressure", "Pa", "p_L, gauge (E33)");
    output(Output::right_control_pressure, "right_control_pressure", "Pa", "p_R, gauge (E33)");
    output(Output::supply_flow, "supply_flow", "m3/s", "flow from supply through the supply metering edge (E36)");
    output(Output::return_flow, "return_flow", "m3/s", "flow to return through the return metering edge (E36)");
    output(Output::saturated, "saturated", "",
           "1 while the flapper rests on a nozzle or the spool on a stroke stop, else 0");
    output(Output::beyond_tables, "beyond_tables", "",
           "1 while a pressure lies beyond the flow tables (constant C_d beyond) or the temperature is held at "
           "a table end, else 0");

    v.push_back({"external_brake_port", Role::parameter, 0, true, "", "",
                 "false: the valve's own brake volume (p_B a state, as `servodrift dynamics'); true: the host "
                 "models the brake and line (brake_port_pressure an input, brake_flow the valve's output)",
                 0.0, {}, {}});
    ValveDescription copy = valve;
    const auto &parameters = valve_parameters();
    for (std::size_t k = 0; k < parameters.size(); ++k)
      v.push_back({parameters[k].name, Role::parameter, k + 1, false, parameters[k].unit, "", parameters[k].description,
                   parameters[k].entry(copy), {}, {}});
    return l;
  }

  const std::vector<UnitDefinition> &unit_definitions()
  {
    static const std::vector<UnitDefinition> units = {
        {"rad", 0, 0, 0, 0, 0, 1, "", 0},        {"rad/s", 0, 0, -1, 0, 0, 1, "", 0},
        {"rad/s2", 0, 0, -2, 0, 0, 1, "", 0},    {"Pa", 1, -1, -2, 0, 0, 0, "", 0},
        {"Pa/s", 1, -1, -3, 0, 0, 0, "", 0},     {"m", 0, 1, 0, 0, 0, 0, "", 0},
        {"m/s", 0, 1, -1, 0, 0, 0, "", 0},       {"m/s2", 0, 1, -2, 0, 0, 0, "", 0},
        {"m3/s", 0, 3, -1, 0, 0, 0, "", 0},      {"A", 0, 0, 0, 1, 0, 0, "", 0},
        {"A/s", 0, 0, -1, 1, 0, 0, "", 0},       {"V", 1, 2, -3, -1, 0, 0, "", 0},
        {"K", 0, 0, 0, 0, 1, 0, "degC", -273.15}};
    return units;
  }
} // namespace servodrift::fmu
