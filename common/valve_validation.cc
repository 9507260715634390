// The checks of a valve description that go beyond one entry's range (declared in
// valve_description.h): every condition that can be checked from the description alone, before
// any stage runs or writes (issue 24). Each parameter struct checks its own entries
// (common/parameters/*_validation.cc); validate() runs them in a fixed order, which decides the
// refusal a description with several faults gets.
#include "common/error.h"
#include "common/parameters/validation_helpers.h"
#include "common/thermal_laws.h"
#include "common/units.h"
#include "common/valve_description.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace servodrift
{
  using namespace validation;

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
    require_increasing(d.cold_start_temperatures, "Dynamics/Cold-start temperatures");
    const auto &tm = v.torque_motor;
    if (tm.voltage_drive && !(tm.coil_resistance > 0 && tm.coil_inductance > 0))
      refuse("Torque motor/Coil inductance", "and `Torque motor/Coil resistance' must be > 0 under voltage drive "
                                             "(`Torque motor/Coil drive' = voltage)");

    // Every current the analyses command must lie in the torque table: bias -+ the largest sine
    // amplitude, the small step, the cold start and the rated current. Under voltage drive the coil current is a
    // state: a cold coil draws R_c(T0)/R_c(T) of the command, and near the armature's resonance the
    // back-EMF lets it overshoot by some 10 %, so the table must reach 1.25 times that.
    double ratio = 1;
    if (tm.voltage_drive)
      {
        for (double T : sw.drift_temperatures)
          ratio = std::max(ratio, laws::coil_resistance(tm, op.reference_temperature) / laws::coil_resistance(tm, T));
        ratio *= 1.25;
      }
    // The commands, each with the entry that asks for it, so that a refusal names that entry
    const double rated = op.rated_current, bias = d.bias * rated;
    const bool check_amplitude_largest = d.sine_check_amplitude > d.sine_amplitudes.back();
    const std::string amplitude_entry = check_amplitude_largest ? "Dynamics/Sine check amplitude" : "Dynamics/Sine amplitudes";
    const double amplitude = (check_amplitude_largest ? d.sine_check_amplitude : d.sine_amplitudes.back()) * rated;
    const std::vector<std::pair<std::string, double>> commands{{amplitude_entry, bias - amplitude},
                                                               {amplitude_entry, bias + amplitude},
                                                               {"Dynamics/Small step", bias + d.small_step * rated},
                                                               {"Dynamics/Cold-start current", d.cold_start_current * rated},
                                                               {"Operating conditions/Rated current", rated}};
    const auto &currents = sw.motor_currents;
    if (!(currents.front() <= 0 && currents.back() >= 0))
      refuse("Sweeps/Motor currents", "from " + format_number(currents.front()) + " to " +
                                        format_number(currents.back()) + " A must hold 0 A, where the dynamics start");
    for (const auto &[entry, command] : commands)
      {
        const double coil = command * ratio;
        if (coil >= currents.front() && coil <= currents.back())
          continue;
        refuse(entry, "with `Dynamics/Bias' = " + format_number(d.bias) + " commands " + format_number(command) + " A" +
                        (tm.voltage_drive ? " (under voltage drive a cold coil's current, with 25 % for its overshoot, " +
                                              format_number(coil) + " A)" :
                                            "") +
                        ", beyond the torque table's `Sweeps/Motor currents' [" + format_number(currents.front()) + ", " +
                        format_number(currents.back()) + "] A; lower it, or extend the currents");
      }
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
      refuse("Sweeps/Motor angles",
             "must reach the nozzle contacts at +-" + format_number(1.001 * contact / units::degree) +
               " deg for the dynamics, where the flapper may hit a nozzle in a transient" +
               (v.offsets.magnetic_null != 0 || v.offsets.hydraulic_null != 0 ?
                  " (they include `Offsets/Magnetic null' = " + format_number(v.offsets.magnetic_null / units::degree) +
                    " deg and `Offsets/Hydraulic null' = " + format_number(v.offsets.hydraulic_null) + " m)" :
                  std::string()) +
               " (or set `Dynamics/Enabled' = false)");
  }

  void validate_table_ranges(const ValveDescription &v)
  {
    // the bridge's control pressure may lie anywhere between return and supply: every pressure
    // list of the pilot tables must reach the whole span p_s - p_r (the reduced-order one from 0)
    const auto &sw = v.sweeps;
    std::vector<std::pair<const std::vector<double> *, const char *>> lists;
    if (v.pilot.model_level == ModelLevel::field)
      lists = {{&sw.field_orifice_pressure_fractions, "Sweeps/Field orifice pressure fractions"},
               {&sw.field_nozzle_pressure_fractions, "Sweeps/Field nozzle pressure fractions"}};
    else
      {
        lists = {{&sw.pressure_fractions, "Sweeps/Pressure fractions"}};
        if (!(sw.pressure_fractions.front() == 0))
          refuse("Sweeps/Pressure fractions", "starts with " + format_number(sw.pressure_fractions.front()) +
                                                "; it must start with 0, the laminar limit of the pilot flows");
      }
    for (const auto &[list, entry] : lists)
      if (!(list->back() == 1))
        refuse(entry, "ends with " + format_number(list->back()) +
                        "; it must end with 1 (p_s - p_r) for `servodrift run': the pilot bridge's control "
                        "pressure may lie anywhere between return and supply");
    if (!v.pilot.field_solution.model_form_alternatives.empty() && v.pilot.model_level != ModelLevel::field)
      refuse("Pilot stage/Field solution/Model-form alternatives",
             "lists other flow models, which only the field level has; set `Pilot stage/Model level' = field or "
             "leave it empty");
  }

  void validate(const ValveDescription &v)
  {
    // Each struct's checks in the order of the refusals: a description with several faults is
    // refused for the first fault in this order
    v.pilot.time_average.validate();
    v.operating.validate();
    v.sweeps.validate();

    // Temperatures inside the oil law's window (E14-E16) and within the table temperatures
    v.fluid.validate();
    v.fluid.validate(v);
    v.sweeps.validate(v);

    // Torque motor: gaps open at every temperature and every tabulated angle (E2, E6, E7); the
    // field model's parts without overlap
    v.torque_motor.validate();
    v.torque_motor.validate(v);
    if (v.torque_motor.model_level == ModelLevel::field)
      v.torque_motor.validate_field_model();

    // Spring tube
    v.spring_tube.validate();
    if (v.spring_tube.model_level == ModelLevel::field)
      v.spring_tube.validate_field_model();
    v.spring_tube.validate(v);

    // Pilot stage, armature and spool
    v.pilot.validate();
    v.pilot.validate(v);
    v.armature.validate();
    v.spool.validate();

    // Parts of the dynamic model that the static model uses as well (E36 leakage, in
    // SpoolParameters::validate()) or that must be physical whatever runs
    v.armature.validate_dynamic_model();
    v.spool.validate_dynamic_model();
    v.pilot.validate_dynamic_model(v);
    v.fluid.validate_dynamic_model(v);
    if (v.dynamics.enabled)
      validate_dynamics(v);
    validate_asymmetry(v);
    validate_null_shift_spec(v); // the report holds the drift map against it too
    if (v.tolerances.enabled)
      validate_tolerances(v);

    // Offsets (C8)
    v.offsets.validate();
  }
} // namespace servodrift
