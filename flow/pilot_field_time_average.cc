#include "flow/pilot_field_time_average.h"

#include <algorithm>
#include <cmath>

namespace servodrift::flow
{
  namespace
  {
    /// Each step's implicit equations are iterated until their scaled residuals fall below this,
    /// or for at most step_iterations SIMPLEC iterations: a step changes the fields little, so its
    /// residuals start low (a few iterations per step). With 1e-4 a steady laminar case marched in
    /// time stays within 1.5e-4 of its steady C_dn (pilot_field_time_average_test.cc).
    constexpr double step_tolerance = 1e-4;
    constexpr unsigned int step_iterations = 50;

    /// Mean and variance by Welford's update (one pass, no cancellation).
    struct RunningMoments
    {
      double count = 0, mean = 0, m2 = 0;
      void add(double x)
      {
        count += 1;
        const double delta = x - mean;
        mean += delta / count;
        m2 += delta * (x - mean);
      }
      double standard_deviation() const { return count > 1 ? std::sqrt(m2 / count) : 0.0; }
    };

    /// Running means of the fields of a case, componentwise (the same update as RunningMoments').
    struct RunningFields
    {
      double count = 0;
      FlowFields mean;
      static std::vector<std::vector<double> *> averaged(FlowFields &f)
      {
        return {&f.u, &f.v, &f.p, &f.flux, &f.k, &f.epsilon, &f.turbulent_viscosity, &f.liquid_fraction};
      }
      void add(FlowFields f)
      {
        count += 1;
        if (count == 1)
          {
            mean = std::move(f);
            return;
          }
        const auto to = averaged(mean), from = averaged(f);
        for (std::size_t i = 0; i < to.size(); ++i)
          for (std::size_t j = 0; j < to[i]->size(); ++j)
            (*to[i])[j] += ((*from[i])[j] - (*to[i])[j]) / count;
      }
      FlowFields result() const
      {
        FlowFields f = mean;
        for (std::size_t c = 0; c < f.cavitating.size(); ++c)
          f.cavitating[c] = f.liquid_fraction[c] < 1;
        return f;
      }
    };
  } // namespace

  TimeAverage time_average(PilotField &field, double dp, const PilotStageParameters &settings,
                           const std::function<void(unsigned int, double, const PilotFieldResult &)> &each_step)
  {
    TimeAverage a;
    a.time_step = field.courant_time_step(settings.field_time_step_courant);
    const unsigned int steps = settings.field_time_steps;
    const unsigned int averaged = std::max(
      2u, std::min(steps, static_cast<unsigned int>(std::lround(settings.field_averaged_fraction * steps))));
    RunningMoments Q, C_d, Re, force, land, jet, bore;
    RunningFields fields;
    PilotFieldResult &m = a.mean;
    for (unsigned int step = 0; step < steps; ++step)
      {
        const PilotFieldResult r = field.advance(dp, a.time_step, step_iterations, step_tolerance);
        m.iterations += r.iterations;
        if (each_step)
          each_step(step + 1, (step + 1) * a.time_step, r);
        if (step + averaged < steps)
          continue;
        Q.add(r.flow_rate), C_d.add(r.discharge_coefficient), Re.add(r.reynolds_number);
        force.add(r.flapper_force), land.add(r.land_force), jet.add(r.jet_force), bore.add(r.bore_pressure);
        fields.add(field.fields());
        const bool first = Q.count == 1;
        m.minimum_pressure = first ? r.minimum_pressure : std::min(m.minimum_pressure, r.minimum_pressure);
        m.minimum_absolute_pressure =
          first ? r.minimum_absolute_pressure : std::min(m.minimum_absolute_pressure, r.minimum_absolute_pressure);
        m.cavitating = m.cavitating || r.cavitating;
        m.max_wall_y_plus = std::max(m.max_wall_y_plus, r.max_wall_y_plus);
        m.pressure_difference = r.pressure_difference, m.turbulence = r.turbulence;
      }
    m.flow_rate = Q.mean, m.discharge_coefficient = C_d.mean, m.reynolds_number = Re.mean;
    m.flapper_force = force.mean, m.land_force = land.mean, m.jet_force = jet.mean, m.bore_pressure = bore.mean;
    a.discharge_coefficient_spread = C_d.standard_deviation();
    a.flapper_force_spread = force.standard_deviation();
    a.averaged_time = averaged * a.time_step;
    a.mean_fields = fields.result();
    return a;
  }
} // namespace servodrift::flow
