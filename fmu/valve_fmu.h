#pragma once
// One instance of the valve FMU: the valve of resources/ (parameters.prm, the coefficient tables,
// provenance.txt) as the same code runs it in `servodrift dynamics': ValveEquations (E29-E37, the
// asymmetry of the described valve) behind ValveDynamics, integrated by CVODE for Co-Simulation.
// The inputs may move the temperature and the supply and return pressures: the equations are
// rebuilt when they change (the tables are interpolated in temperature, C14). Everything an
// instance needs is in it (several instances in one process); errors are exceptions, which
// fmi2_functions.cc turns into logged messages and fmi2Error.
#include "fmu/fmu_variables.h"
#include "system/valve_dynamics.h"
#include "system/valve_model.h"

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace servodrift::fmu
{
  /// What an instance tells its host: a warning (the host goes on) or a note.
  using Log = std::function<void(bool warning, const std::string &message)>;

  /// The state of an instance that fmi2GetFMUstate keeps: enough to go on from it (CVODE restarts).
  struct Snapshot
  {
    double time = 0;
    std::vector<double> states;
    std::array<double, static_cast<std::size_t>(Input::count)> inputs{};
  };

  /// fmi2SerializeFMUstate's bytes: a tag, the number of states, then time, states and inputs.
  std::size_t serialized_size(const Snapshot &s);
  void serialize(const Snapshot &s, char *bytes, std::size_t size);
  /// Throws InputError when the bytes are not a snapshot of this FMU's kind.
  Snapshot deserialize(const char *bytes, std::size_t size);

  class ValveFmu
  {
  public:
    /// Reads `resources' (a directory). Throws InputError naming the file that is missing or bad.
    ValveFmu(const std::string &resources, bool co_simulation, Log log);
    ~ValveFmu();

    const Layout &variables() const { return layout_; }

    // --- fmi2Get/Set (value reference = position in variables()); throw InputError when refused
    double get_real(unsigned int vr);
    void set_real(unsigned int vr, double value);
    bool get_boolean(unsigned int vr) const;
    void set_boolean(unsigned int vr, bool value);

    void setup_experiment(double start_time, double tolerance);
    /// Back to the state after instantiation (fmi2Reset): the described parameters, the start inputs.
    void reset();
    /// After the parameters and the start inputs: the model of the valve with its parameters and the
    /// states at the static operating point of the inputs (all rates zero).
    void exit_initialization();
    bool initialized() const { return initialized_; }

    // --- Model Exchange
    void set_time(double t) { time_ = t; }
    double time() const { return time_; }
    void set_states(const double *x, std::size_t n);
    void get_states(double *x, std::size_t n);
    void derivatives(double *dx, std::size_t n);
    void nominals(double *x, std::size_t n);

    // --- Co-Simulation: integrates from time() to t + h with the inputs held (CVODE, restarted
    // where an input changed)
    void do_step(double t, double h);

    /// The state for fmi2GetFMUstate; the integrator restarts from it, as it will after restore()
    Snapshot save();
    void restore(const Snapshot &s);

  private:
    ValveDescription described; ///< as in resources/
    ValveDescription valve;     ///< with the FMU's parameters
    bool co_simulation;
    Log log;
    Layout layout_;
    std::unique_ptr<system::StageTables> tables;
    std::unique_ptr<system::StageFunctions> functions;
    double lowest_temperature, highest_temperature; ///< the tables' common range [degC]
    bool external_brake_port = false;
    std::array<double, static_cast<std::size_t>(Input::count)> inputs{};
    double time_ = 0, relative_tolerance;

    bool initialized_ = false;
    std::unique_ptr<system::ValveModel> model; ///< null until the start is prepared
    system::Offsets offsets;
    std::vector<double> y; ///< the states (model.md 1.20)

    /// The valve at the inputs' temperature (held at a table end) and pressures, rebuilt when they change
    struct AtInputs
    {
      ValveDescription valve; ///< with the inputs' pressures
      double temperature = 0, supply_pressure = 0, return_pressure = 0;
      std::unique_ptr<system::ValveEquations> equations;
      std::unique_ptr<system::ValveDynamics> dynamics;
    };
    AtInputs at_inputs;
    bool temperature_held = false;
    const system::ValveDynamics &dynamics();

    std::unique_ptr<system::ValveIntegrator> integrator; ///< null: restart at the next step
    std::array<double, static_cast<std::size_t>(Input::count)> integrated_inputs{};

    const Variable &variable(unsigned int vr) const;
    /// The model, the offsets and the static operating point of the inputs, if not yet made
    void prepare();
    /// Forgets them (a parameter or start input changed before initialisation)
    void forget_start();
    double input(Input i) const { return inputs[static_cast<std::size_t>(i)]; }
    /// The states with an external brake port's pressure in p_B
    std::vector<double> states_in_use() const;
    double output(Output o);
  };
} // namespace servodrift::fmu
