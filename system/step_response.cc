#include "system/step_response.h"

#include "common/error.h"
#include "common/units.h"
#include "system/linear_analysis.h"
#include "system/steady_state_check.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

namespace servodrift::system
{
  namespace
  {
    /// Rise time, overshoot and settling time of one signal, from its values within each internal
    /// step of the integrator (s(t) valid on [t_previous, t]). The signal is normalised so that it
    /// goes from 0 (initial) to 1 (final).
    class StepTracker
    {
    public:
      StepTracker(double initial, double final)
      {
        metrics.initial = initial;
        metrics.final = final;
      }

      void observe(double t_previous, double t, const std::function<double(double)> &s)
      {
        if (change() == 0)
          return;
        const auto u = [&](double time) { return (s(time) - metrics.initial) / change(); };
        const double u_a = t_previous == 0 && !started ? 0.0 : last, u_b = u(t);
        started = true;
        const auto crossing = [&](const std::function<double(double)> &g) { // g(t_previous) > 0 >= g(t)
          double a = t_previous, b = t;
          for (int k = 0; k < 60 && b - a > 1e-12 * t; ++k)
            (g(0.5 * (a + b)) > 0 ? a : b) = 0.5 * (a + b);
          return 0.5 * (a + b);
        };
        if (!t10 && u_a < 0.1 && u_b >= 0.1)
          t10 = crossing([&](double x) { return 0.1 - u(x); });
        if (!t90 && u_a < 0.9 && u_b >= 0.9)
          t90 = crossing([&](double x) { return 0.9 - u(x); });
        metrics.overshoot = std::max(metrics.overshoot, 100 * (u_b - 1));
        const bool inside_now = std::abs(u_b - 1) <= 0.02;
        if (inside_now && !inside)
          entry = std::abs(u_a - 1) <= 0.02 ? t_previous : crossing([&](double x) { return std::abs(u(x) - 1) - 0.02; });
        inside = inside_now;
        last = u_b;
      }

      StepMetrics result() const
      {
        StepMetrics m = metrics;
        if (t10 && t90)
          m.rise_time = *t90 - *t10;
        if (inside && change() != 0)
          m.settling_time = entry;
        return m;
      }

    private:
      StepMetrics metrics;
      std::optional<double> t10, t90;
      double entry = 0, last = 0;
      bool inside = false, started = false;
      double change() const { return metrics.final - metrics.initial; }
    };

    /// p_B, x_v and x_f of a state vector
    std::array<double, 3> outputs(const ValveDynamics &d, const std::vector<double> &y)
    {
      return {y[6], y[4], d.equations().flapper_displacement(y[0])};
    }
  } // namespace

  double step_duration(const ValveModel &model, const ValveDynamics &dynamics, double to,
                       const DynamicsParameters &p, double longest)
  {
    if (p.step_duration > 0)
      return p.step_duration;
    const OperatingPoint end = model.solve(dynamics.equations(), dynamics.steady_current(to));
    const double rate = slowest_decay_rate(linearise(dynamics, end.state(), to));
    return std::clamp(8 / rate, 0.02, longest);
  }

  namespace
  {
    /// The response to the command `to' from the state y0, to the static point at `to'
    StepResponse response_from(const ValveModel &model, const ValveDynamics &dynamics, const std::vector<double> &y0,
                               double from, double to, double duration, const DynamicsParameters &p,
                               unsigned int samples, const std::string &what)
  {
    const ValveEquations &eq = dynamics.equations();
    const OperatingPoint end = model.solve(eq, dynamics.steady_current(to));
    StepResponse r;
    r.from_current = from;
    r.to_current = to;
    r.duration = duration;

    const std::vector<double> y1 = dynamics.vector_of(end.state());
    const auto before = outputs(dynamics, y0), after = outputs(dynamics, y1);
    std::vector<StepTracker> trackers;
    for (std::size_t k = 0; k < 3; ++k)
      trackers.emplace_back(before[k], after[k]);

    const auto integrator =
      dynamics.integrator([to](double) { return to; }, p, what + " at " + format_number(eq.temperature()) + " degC", y1);
    integrator->start(0.0, y0);
    eq.forget_table_excursions();
    // half the samples over the whole step, half over its first 10 ms, where the armature moves
    const double early = std::min(r.duration, 0.01);
    // (the fraction first: it is exactly 1 at the last sample, so that the last time is the
    // duration itself and not one rounding beyond the integration's end, where it is never sampled)
    for (unsigned int k = 0; k < samples / 2; ++k)
      {
        const double fraction = double(k) / (samples / 2 - 1);
        r.times.push_back(r.duration * fraction);
        r.times.push_back(early * fraction);
      }
    std::sort(r.times.begin(), r.times.end());
    r.times.erase(std::unique(r.times.begin(), r.times.end()), r.times.end());
    samples = static_cast<unsigned int>(r.times.size());
    r.states.push_back(dynamics.state_of(y0.data(), to));
    std::size_t next_sample = 1;
    const double x0 = eq.null_gap(), stroke = eq.stroke_limit();
    integrator->integrate(r.duration, [&](double t_previous, double t) {
      for (; next_sample < samples && r.times[next_sample] <= t; ++next_sample)
        r.states.push_back(dynamics.state_of(integrator->interpolate(r.times[next_sample]).data(), to));
      for (std::size_t k = 0; k < 3; ++k)
        trackers[k].observe(t_previous, t, [&, k](double time) -> double {
          return outputs(dynamics, time == t ? integrator->y() : integrator->interpolate(time))[k];
        });
      const auto &y = integrator->y();
      r.flapper_contact |= std::abs(eq.flapper_displacement(y[0])) > x0;
      r.spool_on_stop |= std::abs(y[4]) > stroke;
      return true;
    });
    if (r.states.size() != r.times.size())
      throw std::logic_error(what + ": " + std::to_string(r.states.size()) + " states for " +
                             std::to_string(r.times.size()) + " sample times");
    for (std::size_t k = 0; k < 3; ++k)
      r.metrics[k] = trackers[k].result();
    r.final_distance = dynamics.scaled_distance(integrator->y(), y1);
    r.left_tables = eq.left_tables();
    r.statistics = integrator->statistics();
    return r;
  }
  } // namespace

  StepResponse step_response(const ValveModel &model, const ValveDynamics &dynamics, double from, double to,
                             const DynamicsParameters &p, unsigned int samples)
  {
    const OperatingPoint start = model.solve(dynamics.equations(), dynamics.steady_current(from));
    return response_from(model, dynamics, dynamics.vector_of(start.state()), from, to,
                         step_duration(model, dynamics, to, p), p, samples, "step response");
  }

  StepResponse start_up_response(const ValveModel &model, const ValveDynamics &dynamics, double to,
                                 const DynamicsParameters &p, unsigned int samples)
  {
    return response_from(model, dynamics, dynamics.vector_of(rest_state(dynamics.equations())), 0.0, to,
                         step_duration(model, dynamics, to, p, longest_start_up), p, samples, "start-up");
  }
} // namespace servodrift::system
