#include "fmu/valve_fmu.h"

#include "common/error.h"
#include "common/units.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <tuple>

namespace servodrift::fmu
{
  namespace
  {
    /// The first value of a "key value" line of resources/provenance.txt
    std::string provenance_value(const std::string &path, const std::string &key)
    {
      std::ifstream in(path);
      if (!in)
        throw InputError(path + ": cannot be read (the FMU's provenance)");
      for (std::string line; std::getline(in, line);)
        if (line.rfind(key + " ", 0) == 0)
          return line.substr(key.size() + 1);
      throw InputError(path + ": no `" + key + "' line");
    }

    std::string shown(double value)
    {
      std::ostringstream s;
      s.precision(6);
      s << value;
      return s.str();
    }
  } // namespace

  namespace
  {
    constexpr char snapshot_tag[8] = {'s', 'e', 'r', 'v', 'o', 'F', 'M', '1'};
  }

  std::size_t serialized_size(const Snapshot &s)
  {
    return sizeof(snapshot_tag) + sizeof(std::uint64_t) + sizeof(double) * (1 + s.states.size() + s.inputs.size());
  }

  void serialize(const Snapshot &s, char *bytes, std::size_t size)
  {
    if (size < serialized_size(s))
      throw InputError(std::to_string(size) + " bytes, the state needs " + std::to_string(serialized_size(s)));
    const auto put = [&bytes](const void *data, std::size_t n) {
      std::memcpy(bytes, data, n);
      bytes += n;
    };
    const std::uint64_t n = s.states.size();
    put(snapshot_tag, sizeof(snapshot_tag));
    put(&n, sizeof(n));
    put(&s.time, sizeof(double));
    put(s.states.data(), sizeof(double) * s.states.size());
    put(s.inputs.data(), sizeof(double) * s.inputs.size());
  }

  Snapshot deserialize(const char *bytes, std::size_t size)
  {
    Snapshot s;
    std::uint64_t n = 0;
    if (size >= sizeof(snapshot_tag) + sizeof(n))
      std::memcpy(&n, bytes + sizeof(snapshot_tag), sizeof(n));
    if (size < sizeof(snapshot_tag) + sizeof(n) || std::memcmp(bytes, snapshot_tag, sizeof(snapshot_tag)) != 0 ||
        n > 8 || size != sizeof(snapshot_tag) + sizeof(n) + sizeof(double) * (1 + n + s.inputs.size()))
      throw InputError("the bytes are not a state of this FMU");
    const char *p = bytes + sizeof(snapshot_tag) + sizeof(n);
    s.states.resize(n);
    std::memcpy(&s.time, p, sizeof(double));
    std::memcpy(s.states.data(), p + sizeof(double), sizeof(double) * n);
    std::memcpy(s.inputs.data(), p + sizeof(double) * (1 + n), sizeof(double) * s.inputs.size());
    return s;
  }

  ValveFmu::ValveFmu(const std::string &resources, bool co_simulation_, Log log_)
    : described(read_printed_valve_description(resources + "/parameters.prm"))
    , co_simulation(co_simulation_)
    , log(std::move(log_))
  {
    validate(described);
    described.parameters_sha256 = provenance_value(resources + "/provenance.txt", "parameters-sha256");
    valve = described;
    tables = std::make_unique<system::StageTables>(system::StageTables::read(resources + "/tables", valve));
    for (const auto &w : tables->warnings)
      log(true, w);
    functions = std::make_unique<system::StageFunctions>(*tables);
    std::tie(lowest_temperature, highest_temperature) = table_temperature_range(*functions);
    layout_ = layout(valve, *functions);
    reset();
  }

  void ValveFmu::reset()
  {
    valve = described;
    external_brake_port = false;
    for (const auto &v : layout_.variables)
      if (v.role == Role::input)
        inputs[v.index] = *v.start;
    relative_tolerance = valve.dynamics.relative_tolerance;
    time_ = 0;
    initialized_ = false;
    temperature_held = false;
    forget_start();
  }

  ValveFmu::~ValveFmu() = default;

  const Variable &ValveFmu::variable(unsigned int vr) const
  {
    if (vr >= layout_.variables.size())
      throw InputError("value reference " + std::to_string(vr) + " is not one of the FMU's (0 to " +
                       std::to_string(layout_.variables.size() - 1) + ")");
    return layout_.variables[vr];
  }

  void ValveFmu::set_real(unsigned int vr, double value)
  {
    const Variable &v = variable(vr);
    if (v.boolean)
      throw InputError("`" + v.name + "' is a Boolean, not a Real");
    if (!std::isfinite(value))
      throw InputError("`" + v.name + "' = " + shown(value) + " is not a finite number");
    switch (v.role)
      {
      case Role::input:
        inputs[v.index] = value;
        if (!initialized_)
          forget_start();
        return;
      case Role::parameter:
        if (initialized_)
          throw InputError("`" + v.name + "' is fixed after initialisation (set it before)");
        valve_parameters()[v.index - 1].entry(valve) = value;
        forget_start();
        return;
      default:
        throw InputError("`" + v.name +
                         "' cannot be set (only inputs and parameters can; states through "
                         "fmi2SetContinuousStates)");
      }
  }

  double ValveFmu::get_real(unsigned int vr)
  {
    const Variable &v = variable(vr);
    if (v.boolean)
      throw InputError("`" + v.name + "' is a Boolean, not a Real");
    switch (v.role)
      {
      case Role::input: return inputs[v.index];
      case Role::parameter: return valve_parameters()[v.index - 1].entry(valve);
      case Role::state: prepare(); return y[v.index];
      case Role::derivative:
        {
          prepare();
          std::vector<double> dx(y.size());
          derivatives(dx.data(), dx.size());
          return dx[v.index];
        }
      case Role::output: prepare(); return output(static_cast<Output>(v.index));
      }
    return 0;
  }

  bool ValveFmu::get_boolean(unsigned int vr) const
  {
    const Variable &v = variable(vr);
    if (!v.boolean)
      throw InputError("`" + v.name + "' is a Real, not a Boolean");
    return external_brake_port;
  }

  void ValveFmu::set_boolean(unsigned int vr, bool value)
  {
    const Variable &v = variable(vr);
    if (!v.boolean)
      throw InputError("`" + v.name + "' is a Real, not a Boolean");
    if (initialized_)
      throw InputError("`" + v.name + "' is fixed after initialisation (set it before)");
    external_brake_port = value;
    forget_start();
  }

  void ValveFmu::setup_experiment(double start_time, double tolerance)
  {
    time_ = start_time;
    if (tolerance > 0)
      relative_tolerance = tolerance;
  }

  void ValveFmu::forget_start()
  {
    model.reset();
    at_inputs = {};
    integrator.reset();
    y.clear();
  }

  void ValveFmu::prepare()
  {
    if (model)
      return;
    model = std::make_unique<system::ValveModel>(valve, *functions);
    offsets = model->offsets_for_deviation(0.0);
    at_inputs = {};
    at_inputs.valve = valve;
    const system::ValveDynamics &d = dynamics();
    // the static operating point of the start inputs (a blocked brake port)
    const system::OperatingPoint point = model->solve(d.equations(), d.steady_current(input(Input::coil)));
    y = d.vector_of(point.state());
  }

  void ValveFmu::exit_initialization()
  {
    prepare();
    initialized_ = true;
  }

  const system::ValveDynamics &ValveFmu::dynamics()
  {
    double T = input(Input::oil_temperature) - units::celsius_to_kelvin;
    const bool held = T < lowest_temperature || T > highest_temperature;
    if (held && !temperature_held)
      log(true, "oil_temperature = " + shown(T) + " degC is outside the tables' range [" + shown(lowest_temperature) +
                    ", " + shown(highest_temperature) + "] degC: the valve is held at the end value");
    temperature_held = held;
    T = std::clamp(T, lowest_temperature, highest_temperature);
    const double p_s = input(Input::supply_pressure), p_r = input(Input::return_pressure);
    if (at_inputs.dynamics && at_inputs.temperature == T && at_inputs.supply_pressure == p_s &&
        at_inputs.return_pressure == p_r)
      return *at_inputs.dynamics;
    if (!(p_s > p_r))
      throw InputError("supply_pressure = " + shown(p_s) + " Pa must exceed return_pressure = " + shown(p_r) + " Pa");
    if (!model)
      prepare();
    at_inputs.valve.operating.supply_pressure = p_s;
    at_inputs.valve.operating.return_pressure = p_r;
    at_inputs.temperature = T;
    at_inputs.supply_pressure = p_s;
    at_inputs.return_pressure = p_r;
    at_inputs.dynamics.reset();
    at_inputs.equations = std::make_unique<system::ValveEquations>(at_inputs.valve, model->functions(), T, offsets);
    system::HeldParts held_parts;
    held_parts.brake_volume = external_brake_port;
    // the "command" of ValveDynamics is the coil current, or under voltage drive the coil voltage
    // itself (an amplifier of 1 Ohm)
    at_inputs.dynamics =
        std::make_unique<system::ValveDynamics>(*at_inputs.equations, 1.0, valve.operating.rated_current, held_parts);
    integrator.reset();
    return *at_inputs.dynamics;
  }

  std::vector<double> ValveFmu::states_in_use() const
  {
    std::vector<double> s = y;
    if (external_brake_port)
      s[6] = input(Input::brake_port_pressure);
    return s;
  }

  void ValveFmu::set_states(const double *x, std::size_t n)
  {
    if (n != layout_.states)
      throw InputError(std::to_string(n) + " states, the FMU has " + std::to_string(layout_.states));
    for (std::size_t k = 0; k < n; ++k)
      if (!std::isfinite(x[k]))
        throw InputError("`" + layout_.variables[k].name + "' = " + shown(x[k]) + " is not a finite number");
    prepare();
    y.assign(x, x + n);
  }

  void ValveFmu::get_states(double *x, std::size_t n)
  {
    if (n != layout_.states)
      throw InputError(std::to_string(n) + " states, the FMU has " + std::to_string(layout_.states));
    prepare();
    std::copy(y.begin(), y.end(), x);
  }

  void ValveFmu::derivatives(double *dx, std::size_t n)
  {
    if (n != layout_.states)
      throw InputError(std::to_string(n) + " states, the FMU has " + std::to_string(layout_.states));
    prepare();
    const std::vector<double> s = states_in_use();
    dynamics().rates(s.data(), input(Input::coil), dx);
    for (std::size_t k = 0; k < n; ++k)
      if (!std::isfinite(dx[k]))
        throw InputError("the derivative of `" + layout_.variables[k].name + "' is not finite at t = " + shown(time_) +
                         " s");
  }

  void ValveFmu::nominals(double *x, std::size_t n)
  {
    if (n != layout_.states)
      throw InputError(std::to_string(n) + " states, the FMU has " + std::to_string(layout_.states));
    prepare();
    const auto &scales = dynamics().scales();
    std::copy(scales.begin(), scales.end(), x);
  }

  double ValveFmu::output(Output o)
  {
    const system::ValveDynamics &d = dynamics();
    const system::ValveEquations &eq = d.equations();
    const std::vector<double> s_vector = states_in_use();
    const system::ValveState s = d.state_of(s_vector.data(), input(Input::coil));
    switch (o)
      {
      case Output::brake_pressure: return s.brake_pressure;
      case Output::brake_flow: return eq.brake_inflow(s.spool_displacement, s.brake_pressure);
      case Output::spool_position: return s.spool_displacement;
      case Output::flapper_position: return eq.flapper_displacement(s.angle);
      case Output::armature_angle: return s.angle;
      case Output::left_control_pressure: return s.left_pressure;
      case Output::right_control_pressure: return s.right_pressure;
      case Output::supply_flow: return eq.metering(s.spool_displacement, s.brake_pressure).supply_flow;
      case Output::return_flow: return eq.metering(s.spool_displacement, s.brake_pressure).return_flow;
      case Output::saturated:
        {
          const auto gaps = eq.gaps(s.angle);
          return gaps[0] <= 0 || gaps[1] <= 0 || std::abs(s.spool_displacement) >= eq.stroke_limit() ? 1 : 0;
        }
      case Output::beyond_tables:
        {
          eq.forget_table_excursions();
          eq.rates(s, d.input(input(Input::coil)));
          return eq.left_tables() || temperature_held ? 1 : 0;
        }
      case Output::count: break;
      }
    return 0;
  }

  void ValveFmu::do_step(double t, double h)
  {
    if (!co_simulation)
      throw InputError("an instance for Model Exchange cannot step");
    if (!initialized_)
      throw InputError("before fmi2ExitInitializationMode");
    if (!(h > 0) || !std::isfinite(t) || !std::isfinite(h))
      throw InputError("a step of " + shown(h) + " s at t = " + shown(t) + " s");
    const system::ValveDynamics &d = dynamics();
    if (!integrator || inputs != integrated_inputs || t != time_)
      {
        y = states_in_use();
        DynamicsParameters p = valve.dynamics;
        p.relative_tolerance = relative_tolerance;
        const double command = input(Input::coil);
        integrator = d.integrator([command](double) { return command; }, p,
                                  "the FMU at " + shown(d.equations().temperature()) + " degC", y);
        integrator->start(t, y);
        integrated_inputs = inputs;
      }
    y = integrator->advance_to(t + h);
    time_ = t + h;
  }

  Snapshot ValveFmu::save()
  {
    // CVODE restarts from a saved state, here as after a restore: both paths then step alike
    integrator.reset();
    return {time_, y, inputs};
  }

  void ValveFmu::restore(const Snapshot &s)
  {
    if (s.states.size() != layout_.states)
      throw InputError("a state of another FMU");
    prepare();
    time_ = s.time;
    y = s.states;
    inputs = s.inputs;
    integrator.reset();
  }
} // namespace servodrift::fmu
