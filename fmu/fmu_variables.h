#pragma once
// The valve FMU's variables, written once as data: the states of model.md 1.20 and their
// derivatives, the inputs, the outputs and the parameters (the assembly offsets and the asymmetric
// valve's entries), each with its name, SI unit, description and range. modelDescription.xml is
// written from this list and the FMU's fmi2Get/Set read it, so the two cannot disagree.
#include "common/valve_description.h"
#include "system/stage_tables.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace servodrift::fmu
{
  enum class Role
  {
    state,      ///< a continuous state (causality local)
    derivative, ///< the derivative of a state (causality local)
    input,
    output,
    parameter ///< fixed after initialisation
  };

  /// The inputs, in value-reference order.
  enum class Input : std::size_t
  {
    coil,                ///< coil current [A], or coil voltage [V] under voltage drive
    supply_pressure,     ///< gauge [Pa]
    return_pressure,     ///< gauge [Pa]
    oil_temperature,     ///< [K]
    brake_port_pressure, ///< gauge [Pa], with an external brake port
    count
  };

  /// The outputs, in value-reference order.
  enum class Output : std::size_t
  {
    brake_pressure,
    brake_flow,
    spool_position,
    flapper_position,
    armature_angle,
    left_control_pressure,
    right_control_pressure,
    supply_flow,
    return_flow,
    saturated,
    beyond_tables,
    count
  };

  struct Variable
  {
    std::string name;
    Role role;
    std::size_t index;    ///< the state's, input's, output's or parameter's number
    bool boolean = false; ///< fmi2Boolean, else fmi2Real
    std::string unit;     ///< SI, one of unit_definitions(); empty for numbers of unit 1 and Booleans
    std::string display_unit;
    std::string description;
    std::optional<double> start, min, max;
  };

  /// A parameter of the FMU: an entry of the valve description (SI), set before initialisation.
  struct Parameter
  {
    std::string name, unit, description;
    std::function<double &(ValveDescription &)> entry;
  };

  /// The parameters other than `external_brake_port' (the first parameter, a Boolean).
  const std::vector<Parameter> &valve_parameters();

  struct Layout
  {
    bool voltage_drive = false;
    std::size_t states = 0;          ///< 7, or 8 under voltage drive (the coil current)
    std::vector<Variable> variables; ///< value reference = position in this list
    /// The value reference of the first variable of each role
    unsigned int first(Role role) const;
  };

  /// The temperatures every table covers: the highest of their lowest to the lowest of their highest [degC]
  std::pair<double, double> table_temperature_range(const system::StageFunctions &f);

  /// The variables of the valve as described over its tables: the temperature's range is the
  /// tables' common one, the coil current's the torque table's.
  Layout layout(const ValveDescription &valve, const system::StageFunctions &tables);

  /// The SI units the variables use: name and exponents (kg, m, s, A, K, rad) and degC for K.
  struct UnitDefinition
  {
    std::string name;
    int kg = 0, m = 0, s = 0, A = 0, K = 0, rad = 0;
    std::string display_unit;  ///< "" or degC for K
    double display_offset = 0; ///< display value = value + offset
  };
  const std::vector<UnitDefinition> &unit_definitions();
} // namespace servodrift::fmu
