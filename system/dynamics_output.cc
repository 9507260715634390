#include "system/dynamics_output.h"

#include "common/csv.h"
#include "common/error.h"
#include "common/output_files.h"
#include "common/units.h"
#include "common/version.h"

#include <cmath>
#include <stdexcept>

namespace servodrift::system
{
  double decibel(std::complex<double> h)
  {
    return 20 * std::log10(std::abs(h));
  }

  double degrees(std::complex<double> h)
  {
    return std::arg(h) / units::degree;
  }

  namespace
  {
    /// A cell; a value that is not finite is a defect, never written.
    std::string cell(double v)
    {
      if (!std::isfinite(v))
        throw std::logic_error("dynamics output: a non-finite value reached a CSV cell");
      return format_cell(v);
    }
    std::string cell(const std::optional<double> &v)
    {
      return v ? cell(*v) : "";
    }
    std::string flag(bool b)
    {
      return b ? "1" : "0";
    }

    CsvDocument document(const ValveDescription &valve, const std::string &name, const std::string &what)
    {
      CsvDocument doc;
      const auto &p = valve.dynamics;
      doc.comments = {"servodrift-output " + name, what,
                      "bias " + format_number(p.bias * valve.operating.rated_current) + " A (" +
                        format_number(100 * p.bias) + " % of rated), coil drive " +
                        (valve.torque_motor.voltage_drive ? "voltage" : "current") + ", brake port " +
                        (valve.spool.brake_port == SpoolParameters::BrakePort::blocked_port ? "blocked at the valve" :
                                                                                              "into the brake volume"),
                      "producer " + producer_string("system/dynamics"),
                      "parameters-sha256 " + valve.parameters_sha256};
      return doc;
    }

    void modes(const ValveDescription &valve, const DynamicsResults &r, const std::string &dir)
    {
      CsvDocument doc = document(valve, "modes",
                                 "eigenvalues of the valve linearised at the bias; a complex pair once (Im > 0); named "
                                 "after the states with a quarter or more of the participation");
      doc.columns = {"temperature[degC]", "mode[-]", "eigenvalue_real[1/s]", "eigenvalue_imaginary[rad/s]",
                     "natural_frequency[Hz]", "damping_ratio[1]", "participation_armature_flapper[1]",
                     "participation_pilot_pressures[1]", "participation_spool[1]", "participation_brake_volume[1]",
                     "participation_coil[1]"};
      for (const auto &d : r.temperatures)
        for (const auto &m : d.modes)
          {
            std::vector<std::string> row = {cell(d.temperature), m.name, cell(m.eigenvalue.real()),
                                            cell(m.eigenvalue.imag()), cell(m.natural_frequency), cell(m.damping_ratio)};
            for (double p : m.participation)
              row.push_back(cell(p));
            doc.rows.push_back(row);
          }
      write_file_atomically(dir + "/modes.csv", doc.text());
    }

    void frequency_response(const ValveDescription &valve, const DynamicsResults &r, const std::string &dir)
    {
      CsvDocument doc = document(valve, "frequency_response",
                                 "linearised transfer functions from the command current, at the bias, brake port "
                                 "blocked (no load flow); amplitude in dB relative to the DC gain, phase relative "
                                 "to it, continuous from the lowest frequency");
      doc.columns = {"temperature[degC]", "frequency[Hz]", "brake_pressure_gain[Pa/A]", "brake_pressure_amplitude[dB]",
                     "brake_pressure_phase[deg]", "spool_displacement_gain[m/A]", "spool_displacement_amplitude[dB]",
                     "spool_displacement_phase[deg]"};
      for (const auto &d : r.temperatures)
        for (std::size_t k = 0; k < d.brake_pressure.frequencies.size(); ++k)
          doc.rows.push_back({cell(d.temperature), cell(d.brake_pressure.frequencies[k]),
                              cell(std::abs(d.brake_pressure.values[k])), cell(d.brake_pressure.amplitude_db[k]),
                              cell(d.brake_pressure.phase_degrees[k]), cell(std::abs(d.spool_displacement.values[k])),
                              cell(d.spool_displacement.amplitude_db[k]), cell(d.spool_displacement.phase_degrees[k])});
      write_file_atomically(dir + "/frequency_response.csv", doc.text());
    }

    void step_responses(const ValveDescription &valve, const DynamicsResults &r, const std::string &dir)
    {
      CsvDocument doc = document(valve, "step_response",
                                 "nonlinear step responses from the static operating point of the first current: "
                                 "large = 0 -> rated current, small = bias -> bias + `Dynamics/Small step'; "
                                 "cold-start = from rest (every pressure at return) with supply and `Dynamics/"
                                 "Cold-start current' applied, at `Dynamics/Cold-start temperatures'");
      doc.columns = {"temperature[degC]", "step[-]", "time[s]", "command_current[A]", "coil_current[A]", "angle[rad]",
                     "flapper_displacement[m]", "left_pressure[Pa]", "right_pressure[Pa]", "spool_displacement[m]",
                     "brake_pressure[Pa]"};
      CsvDocument metrics = document(valve, "step_metrics",
                                     "rise time 10-90 %, overshoot beyond the final value in % of the change, 2 % "
                                     "settling time; initial and final are the static operating points; an empty "
                                     "time was not reached");
      metrics.columns = {"temperature[degC]", "step[-]", "output[-]", "initial[SI]", "final[SI]", "rise_time[s]",
                         "overshoot[%]", "settling_time[s]", "duration[s]", "final_distance[1]", "flapper_contact[-]",
                         "spool_on_stop[-]", "beyond_tables[-]", "steps[1]"};
      const double r_pivot = valve.armature.pivot_to_nozzle_distance;
      const auto add = [&](double T, const char *name, const StepResponse *s, double hydraulic_null) {
        for (std::size_t k = 0; k < s->times.size(); ++k)
          {
            const ValveState &x = s->states[k];
            doc.rows.push_back({cell(T), name, cell(s->times[k]), cell(k == 0 ? s->from_current : s->to_current),
                                cell(x.coil_current), cell(x.angle), cell(r_pivot * x.angle - hydraulic_null),
                                cell(x.left_pressure), cell(x.right_pressure), cell(x.spool_displacement),
                                cell(x.brake_pressure)});
          }
        for (std::size_t k = 0; k < step_outputs.size(); ++k)
          {
            const StepMetrics &m = s->metrics[k];
            metrics.rows.push_back({cell(T), name, step_outputs[k], cell(m.initial), cell(m.final), cell(m.rise_time),
                                    cell(m.overshoot), cell(m.settling_time), cell(s->duration), cell(s->final_distance),
                                    flag(s->flapper_contact), flag(s->spool_on_stop), flag(s->left_tables),
                                    cell(double(s->statistics.steps))});
          }
      };
      for (const auto &d : r.temperatures)
        {
          add(d.temperature, "large", &d.large_step, d.hydraulic_null);
          add(d.temperature, "small", &d.small_step, d.hydraulic_null);
        }
      const double hydraulic_null = r.temperatures.empty() ? 0.0 : r.temperatures.front().hydraulic_null;
      for (const ColdStart &c : r.cold_starts)
        add(c.temperature, "cold-start", &c.response, hydraulic_null);
      write_file_atomically(dir + "/step_response.csv", doc.text());
      write_file_atomically(dir + "/step_metrics.csv", metrics.text());
    }

    void sine_responses(const ValveDescription &valve, const DynamicsResults &r, const std::string &dir)
    {
      CsvDocument doc = document(valve, "sine_response",
                                 "nonlinear sine responses about the bias: check = the small-signal sine the "
                                 "linearity check takes (the smallest amplitude of its halvings), check-halving = the "
                                 "larger amplitudes halved down to it (until halving moves p_B's first harmonic by at "
                                 "most " + format_number(SineCheckLimits::halving_fraction * SineCheckLimits::decibel) +
                                 " dB and " + format_number(SineCheckLimits::halving_fraction * SineCheckLimits::degree) +
                                 " deg, or " + std::to_string(SineCheckLimits::halvings) + " halvings), study-up and study-down = `Dynamics/Sine amplitudes' with "
                                 "the frequencies swept up and down, each starting from its neighbour's periodic "
                                 "state; first harmonics over the input's, amplitude in dB relative to the linear DC "
                                 "gain of each output; integration_failed = the time integration stopped (the "
                                 "report names why), not periodic");
      doc.columns = {"temperature[degC]", "frequency[Hz]", "kind[-]", "amplitude_of_rated[1]", "amplitude[A]",
                     "brake_pressure_amplitude[dB]", "brake_pressure_phase[deg]", "linear_brake_pressure_amplitude[dB]",
                     "linear_brake_pressure_phase[deg]", "spool_displacement_amplitude[dB]",
                     "spool_displacement_phase[deg]", "flapper_displacement_amplitude[dB]", "flapper_displacement_phase[deg]",
                     "periodic[-]", "response_periods[1]", "periods[1]", "distortion[1]", "subharmonic[1]",
                     "brake_pressure_minimum[Pa]", "brake_pressure_maximum[Pa]", "spool_displacement_minimum[m]",
                     "spool_displacement_maximum[m]", "flapper_contact[-]", "beyond_lap[-]", "spool_on_stop[-]",
                     "beyond_tables[-]", "integration_failed[-]"};
      const double rated = valve.operating.rated_current;
      for (const auto &d : r.temperatures)
        {
          for (std::size_t j = 0; j < d.sine_checks.size(); ++j)
            {
              const SineCheck &c = d.sine_checks[j];
              const auto &dc = c.dc_gain;
              auto row = [&](const char *kind, const SineResponse &s) {
                // a response whose integration failed within its first period has no harmonics
                const bool measured = s.periods > 0;
                const auto in = [&](double v) { return measured ? cell(v) : std::string(); };
                doc.rows.push_back(
                  {cell(d.temperature), cell(s.frequency), kind, cell(s.amplitude / rated), cell(s.amplitude),
                   in(decibel(s.gain[0] / dc[0])), in(degrees(s.gain[0] / dc[0])), cell(decibel(c.linear[0] / dc[0])),
                   cell(degrees(c.linear[0] / dc[0])), in(decibel(s.gain[1] / dc[1])), in(degrees(s.gain[1] / dc[1])),
                   in(decibel(s.gain[2] / dc[2])), in(degrees(s.gain[2] / dc[2])), flag(s.periodic),
                   cell(double(s.response_periods)), cell(double(s.periods)), in(s.distortion), in(s.subharmonic),
                   in(s.minimum[0]), in(s.maximum[0]), in(s.minimum[1]), in(s.maximum[1]), flag(s.flapper_contact),
                   flag(s.beyond_lap), flag(s.spool_on_stop), flag(s.left_tables), flag(!s.failure.empty())});
              };
              for (std::size_t k = 0; k + 1 < c.halvings.size(); ++k)
                row("check-halving", c.halvings[k]);
              row(c.linear_limit ? "check" : "check-not-at-linear-limit", c.taken());
              if (d.sine_study.empty()) // the study ran at other temperatures
                continue;
              for (const SineResponse &s : d.sine_study[j])
                row("study-up", s);
              for (const SineResponse &s : d.sine_study_down[j])
                row("study-down", s);
            }
        }
      write_file_atomically(dir + "/sine_response.csv", doc.text());
    }

    void summary(const ValveDescription &valve, const DynamicsResults &r, const std::string &dir)
    {
      CsvDocument doc = document(valve, "dynamics_summary",
                                 "per temperature: the bias point, the brake pressure's -3 dB bandwidth and -90 degree "
                                 "frequency, the armature mode (coupled, at the bias), the closed-form checks at the "
                                 "null (model.md 2.5, C13) and the steady-state checks (scaled distances)");
      doc.columns = {"temperature[degC]", "bias_brake_pressure[Pa]", "bias_spool_displacement[m]", "bias_spool_state[-]",
                     "bandwidth[Hz]", "phase_90_frequency[Hz]", "armature_natural_frequency[Hz]",
                     "armature_damping_ratio[1]", "armature_closed_form[Hz]", "armature_blocked[Hz]",
                     "armature_compressible[Hz]", "armature_coupled_at_null[Hz]", "pressure_time_constant_closed_form[s]",
                     "pressure_time_constant_tables[s]", "pressure_time_constant[s]", "drift_from_static[1]",
                     "distance_from_rest[1]", "settling_from_rest[s]", "unstable_modes[1]"};
      for (const auto &d : r.temperatures)
        {
          const Mode *armature = nullptr;
          for (const auto &m : d.modes)
            if (!armature || m.participation[0] > armature->participation[0])
              armature = &m;
          const auto &c = d.checks;
          std::size_t unstable = 0;
          for (const auto &m : d.modes)
            unstable += m.eigenvalue.real() > 0;
          doc.rows.push_back({cell(d.temperature), cell(d.bias_point.brake_pressure), cell(d.bias_point.spool_displacement),
                              to_string(d.bias_spool_state), cell(d.brake_pressure.bandwidth),
                              cell(d.brake_pressure.phase_90_frequency), cell(armature->natural_frequency),
                              cell(armature->damping_ratio), cell(c.armature_closed_form), cell(c.armature_blocked),
                              cell(c.armature_compressible), cell(c.armature_coupled),
                              cell(c.pressure_time_constant_closed_form), cell(c.pressure_time_constant_tables),
                              cell(c.pressure_time_constant), cell(d.steady.drift_from_static),
                              cell(d.steady.distance_from_rest), cell(d.steady.settling_from_rest),
                              cell(double(unstable))});
        }
      write_file_atomically(dir + "/dynamics_summary.csv", doc.text());
    }

    void fixed_time(const ValveDescription &valve, const std::vector<FixedTimeStudy> &studies, const std::string &dir)
    {
      CsvDocument doc = document(valve, "fixed_time_study",
                                 "model.md C9: drift measures read at fixed times of the start-up from rest, each "
                                 "deviation angle against 0; reading_time 'static' rows are the steady state");
      doc.columns = {"deviation_angle[deg]", "reading_time[s]", "temperature[degC]", "spool_displacement_deviation[m]",
                     "brake_pressure_deviation[Pa]"};
      for (const FixedTimeStudy &s : studies)
      for (std::size_t j = 0; j <= s.reading_times.size(); ++j)
        for (std::size_t k = 0; k < s.temperatures.size(); ++k)
          {
            const bool steady = j == s.reading_times.size();
            doc.rows.push_back({cell(s.deviation_angle / units::degree), steady ? "static" : cell(s.reading_times[j]),
                                cell(s.temperatures[k]),
                                cell(steady ? s.static_displacement_deviation[k] : s.displacement_deviation[j][k]),
                                cell(steady ? s.static_pressure_deviation[k] : s.pressure_deviation[j][k])});
          }
      write_file_atomically(dir + "/fixed_time_study.csv", doc.text());
    }
  } // namespace

  void write_dynamics_tables(const ValveDescription &valve, const DynamicsResults &r, const std::string &dir)
  {
    modes(valve, r, dir);
    frequency_response(valve, r, dir);
    step_responses(valve, r, dir);
    sine_responses(valve, r, dir);
    summary(valve, r, dir);
    if (!r.fixed_time.empty())
      fixed_time(valve, r.fixed_time, dir);
  }
} // namespace servodrift::system
