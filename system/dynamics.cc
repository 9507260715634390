#include "system/dynamics.h"

#include "common/sweep_objects.h"
#include "common/thermal_laws.h"
#include "system/dynamics_serialization.h"

#include <boost/serialization/utility.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace servodrift::system
{
  bool sweeps_differ(const SineResponse &up, const SineResponse &down)
  {
    if (!up.periodic || !down.periodic) // an unsettled response proves nothing
      return false;
    const auto h = up.gain[0] / down.gain[0];
    return std::abs(20 * std::log10(std::abs(h))) > 1 || std::abs(std::arg(h)) > 10 * 3.14159265358979323846 / 180;
  }

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

    /// A temperature's linearity check at one frequency. None where the bias point is unstable: the
    /// valve oscillates there by itself, there is no linear response to check, and a forced response
    /// is the free oscillation's (the step responses show it).
    std::optional<SineCheck> check(const ValveModel &model, const ValveDynamics &dynamics, const OperatingPoint &point,
                                   const Linearisation &l, double bias, double f)
    {
      if (slowest_decay_rate(l) <= 0)
        return std::nullopt;
      const auto &p = model.description().dynamics;
      return sine_check(dynamics, l, point.state(), bias, f, p.sine_check_amplitude * model.description().operating.rated_current, p);
    }

    /// The large-signal study at one amplitude: the sine frequencies swept up, each starting from the
    /// periodic state of the one below, then down likewise; by ascending frequency both.
    using Sweeps = std::optional<std::pair<std::vector<SineResponse>, std::vector<SineResponse>>>;
    Sweeps sweeps(const ValveModel &model, const ValveDynamics &dynamics, const OperatingPoint &point,
                  const Linearisation &l, double bias, double amplitude)
    {
      if (slowest_decay_rate(l) <= 0)
        return std::nullopt;
      const auto &p = model.description().dynamics;
      const std::size_t n = p.sine_frequencies.size();
      const auto sweep = [&](bool up) {
        std::vector<SineResponse> responses(n);
        const std::vector<double> *start = nullptr;
        for (std::size_t j = 0; j < n; ++j)
          {
            const std::size_t k = up ? j : n - 1 - j;
            responses[k] = sine_response(dynamics, l, point.state(), bias, p.sine_frequencies[k], amplitude, p, start);
            start = responses[k].periodic ? &responses[k].final_state : nullptr;
          }
        return responses;
      };
      return std::make_pair(sweep(true), sweep(false));
    }
  } // namespace

  std::vector<std::size_t> study_indices(std::size_t n, std::size_t count)
  {
    if (count >= n)
      count = n;
    std::vector<std::size_t> indices;
    for (std::size_t k = 0; k < count; ++k)
      {
        const std::size_t index = count == 1 ? 0 : (k * (n - 1) + (count - 1) / 2) / (count - 1); // rounded
        if (indices.empty() || indices.back() != index)
          indices.push_back(index);
      }
    return indices;
  }

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

    // cases: first each temperature's linear analyses and steps, then each study temperature's
    // sweeps at each study amplitude (the costliest first), then each temperature and frequency's
    // check, then the cold-soak starts
    const std::size_t n_a = p.sine_amplitudes.size();
    const std::vector<std::size_t> studied = study_indices(n_T, p.large_signal_temperatures);
    const std::size_t n_S = studied.size(), first_check = n_T + n_S * n_a, first_cold = first_check + n_T * n_f;
    // the cold-soak starts the tables reach
    std::vector<double> cold;
    for (double T : p.cold_start_temperatures)
      if (T >= valve.sweeps.table_temperatures.front() && T <= valve.sweeps.table_temperatures.back())
        cold.push_back(T);
    const std::size_t n_C = cold.size();
    const CaseRows rows = run_sweep(
      "dynamics", first_cold + n_C,
      [&](std::size_t c) {
        if (c >= first_cold) // a cold-soak start, at its own temperature
          {
            const double T = cold[c - first_cold];
            const ValveDynamics dynamics(model.equations(T, offsets), amplifier, rated);
            return CaseRows{row_of(ColdStart{T, start_up_response(model, dynamics, p.cold_start_current * rated, p, 600)})};
          }
        const std::size_t k = c < n_T ? c : c < first_check ? studied[(c - n_T) / n_a] : (c - first_check) / n_f;
        const ValveDynamics dynamics(model.equations(temperatures[k], offsets), amplifier, rated);
        const OperatingPoint point = model.solve(dynamics.equations(), dynamics.steady_current(bias));
        const Linearisation l = linearise(dynamics, point.state(), bias);
        if (c < n_T)
          return CaseRows{row_of(linear_and_steps(model, dynamics, point, l, bias))};
        if (c < first_check)
          return CaseRows{row_of(sweeps(model, dynamics, point, l, bias, p.sine_amplitudes[(c - n_T) % n_a] * rated))};
        return CaseRows{row_of(check(model, dynamics, point, l, bias, p.sine_frequencies[(c - first_check) % n_f]))};
      },
      progress);

    DynamicsResults results;
    for (std::size_t k = 0; k < n_T; ++k)
      {
        TemperatureDynamics d = object_of<TemperatureDynamics>(rows[k]);
        const auto s = std::find(studied.begin(), studied.end(), k);
        std::vector<Sweeps> study;
        for (std::size_t a = 0; s != studied.end() && a < n_a; ++a)
          study.push_back(object_of<Sweeps>(rows[n_T + std::size_t(s - studied.begin()) * n_a + a]));
        for (std::size_t j = 0; j < n_f; ++j)
          if (auto c = object_of<std::optional<SineCheck>>(rows[first_check + k * n_f + j]))
            {
              d.sine_checks.push_back(std::move(*c));
              if (study.empty())
                continue;
              d.sine_study.emplace_back();
              d.sine_study_down.emplace_back();
              for (const auto &sweep : study) // stable at the bias, so each sweep exists
                {
                  d.sine_study.back().push_back(sweep->first[j]);
                  d.sine_study_down.back().push_back(sweep->second[j]);
                }
            }
        results.temperatures.push_back(std::move(d));
      }
    for (std::size_t c = 0; c < n_C; ++c)
      results.cold_starts.push_back(object_of<ColdStart>(rows[first_cold + c]));
    if (p.fixed_time_study)
      results.fixed_time = fixed_time_study(model, amplifier, progress);
    return results;
  }
} // namespace servodrift::system
