#include "system/dynamics.h"

#include "common/sweep_objects.h"
#include "common/thermal_laws.h"
#include "system/dynamics_serialization.h"

#include <boost/serialization/utility.hpp>

#include <algorithm>
#include <utility>

namespace servodrift::system
{
  bool TemperatureDynamics::stable() const
  {
    return std::none_of(modes.begin(), modes.end(), [](const Mode &m) { return m.eigenvalue.real() > 0; });
  }

  double amplifier_resistance(const ValveDescription &valve)
  {
    return laws::coil_resistance(valve.torque_motor, valve.operating.reference_temperature);
  }

  namespace
  {
    /// A temperature's linear analyses, checks and step responses.
    TemperatureDynamics linear_and_steps(const ValveModel &model, const ValveDynamics &dynamics,
                                         const OperatingPoint &point, const Linearisation &l, double bias)
    {
      const auto &p = model.description().dynamics;
      const double rated = model.description().operating.rated_current;
      TemperatureDynamics d;
      d.temperature = dynamics.equations().temperature();
      d.bias = bias;
      d.bias_point = point.state();
      d.hydraulic_null = dynamics.equations().offsets().hydraulic_null;
      d.bias_spool_state = point.spool.state;
      d.modes = modes(l);
      d.brake_pressure =
        frequency_response(l, Output::brake_pressure, p.minimum_frequency, p.maximum_frequency, p.frequency_points);
      d.spool_displacement =
        frequency_response(l, Output::spool_displacement, p.minimum_frequency, p.maximum_frequency, p.frequency_points);
      d.checks = dynamic_checks(model, dynamics);
      d.steady = steady_state_check(model, dynamics, bias, p);
      d.large_step = step_response(model, dynamics, 0.0, rated, p, 600);
      d.small_step = step_response(model, dynamics, bias, bias + p.small_step * rated, p, 600);
      return d;
    }

    using Sines = std::optional<std::pair<SineCheck, std::vector<SineResponse>>>;

    /// A temperature's sine responses at one frequency: the linearity check and the study. None
    /// where the bias point is unstable: the valve oscillates there by itself, there is no linear
    /// response to check, and a forced response is the free oscillation's (the step shows it).
    Sines sines(const ValveModel &model, const ValveDynamics &dynamics, const OperatingPoint &point,
                const Linearisation &l, double bias, double f)
    {
      if (slowest_decay_rate(l) <= 0)
        return std::nullopt;
      const auto &p = model.description().dynamics;
      const double rated = model.description().operating.rated_current;
      SineCheck check;
      check.frequency = f;
      for (std::size_t k = 0; k < 3; ++k)
        {
          check.linear[k] = transfer(l, sine_outputs[k], f);
          check.dc_gain[k] = transfer(l, sine_outputs[k], 0.0);
        }
      const double a = linear_amplitude(dynamics, l, point.state(), f, p.sine_check_amplitude * rated, p.linearity_margin);
      check.at_amplitude = sine_response(dynamics, l, point.state(), bias, f, a, p);
      check.at_half = sine_response(dynamics, l, point.state(), bias, f, a / 2, p);
      std::vector<SineResponse> study;
      for (double amplitude : p.sine_amplitudes)
        study.push_back(sine_response(dynamics, l, point.state(), bias, f, amplitude * rated, p));
      return std::make_pair(check, study);
    }
  } // namespace

  DynamicsResults compute_dynamics(const ValveModel &model, OutputParameters::Progress progress)
  {
    const ValveDescription &valve = model.description();
    const auto &p = valve.dynamics;
    const double rated = valve.operating.rated_current, amplifier = amplifier_resistance(valve);
    const std::vector<double> &temperatures = valve.sweeps.drift_temperatures;
    const std::size_t n_T = temperatures.size(), n_f = p.sine_frequencies.size();
    // the valve as described: its own offsets, nulled by the convention of D8
    const Offsets offsets = model.offsets_for_deviation(0.0);
    const double bias = p.bias * rated;

    // cases: first each temperature's linear analyses and steps (the costliest), then each
    // temperature and sine frequency
    const CaseRows rows = run_sweep(
      "dynamics", n_T * (1 + n_f),
      [&](std::size_t c) {
        const double T = temperatures[c < n_T ? c : (c - n_T) / n_f];
        const ValveDynamics dynamics(model.equations(T, offsets), amplifier, rated);
        const OperatingPoint point = model.solve(dynamics.equations(), dynamics.steady_current(bias));
        const Linearisation l = linearise(dynamics, point.state(), bias);
        if (c < n_T)
          return CaseRows{row_of(linear_and_steps(model, dynamics, point, l, bias))};
        return CaseRows{row_of(sines(model, dynamics, point, l, bias, p.sine_frequencies[(c - n_T) % n_f]))};
      },
      progress);

    DynamicsResults results;
    for (std::size_t k = 0; k < n_T; ++k)
      {
        TemperatureDynamics d = object_of<TemperatureDynamics>(rows[k]);
        for (std::size_t j = 0; j < n_f; ++j)
          {
            if (auto computed = object_of<Sines>(rows[n_T + k * n_f + j]))
              {
                d.sine_checks.push_back(std::move(computed->first));
                d.sine_study.push_back(std::move(computed->second));
              }
          }
        results.temperatures.push_back(std::move(d));
      }
    if (p.fixed_time_study)
      results.fixed_time = fixed_time_study(model, amplifier, progress);
    return results;
  }
} // namespace servodrift::system
