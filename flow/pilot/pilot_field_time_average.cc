#include "flow/pilot/pilot_field_time_average.h"

#include "common/error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace servodrift::flow
{
  namespace
  {
    /// Batches of the standard error of a mean: 10 gives the error estimate itself about 25 %
    /// accuracy (9 degrees of freedom) while each batch still spans a tenth of the averaged time.
    constexpr std::size_t mean_batches = 10;

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

  double batch_means_standard_error(const std::vector<double> &series, std::size_t batches)
  {
    batches = std::min(batches, series.size());
    if (batches < 2)
      return 0.0;
    RunningMoments means;
    for (std::size_t b = 0; b < batches; ++b)
      {
        const std::size_t begin = b * series.size() / batches, end = (b + 1) * series.size() / batches;
        double sum = 0;
        for (std::size_t i = begin; i < end; ++i)
          sum += series[i];
        means.add(sum / double(end - begin));
      }
    // the sample variance of the batch means (n - 1 in the denominator), over the number of batches
    return means.standard_deviation() * std::sqrt(1.0 / double(batches - 1));
  }

  std::size_t decorrelation_lag(const std::vector<double> &series)
  {
    const std::size_t n = series.size();
    if (n < 3)
      return 0;
    RunningMoments moments;
    for (double x : series)
      moments.add(x);
    if (!(moments.m2 > 0))
      return 0;
    // (the sum's sign is the autocorrelation's, whichever normalisation)
    for (std::size_t lag = 1; lag < n; ++lag)
      {
        double sum = 0;
        for (std::size_t i = 0; i + lag < n; ++i)
          sum += (series[i] - moments.mean) * (series[i + lag] - moments.mean);
        if (sum <= 0)
          return lag;
      }
    return n;
  }

  bool window_spans_motion(const TimeAverage &a)
  {
    const bool steady = a.discharge_coefficient_spread <= steady_spread * std::abs(a.mean.discharge_coefficient) &&
                        a.flapper_force_spread <= steady_spread * std::abs(a.mean.flapper_force);
    return steady || a.averaged_steps >= lags_per_window * std::size_t(a.decorrelation_steps);
  }

  bool steps_converged(const TimeAverage &a)
  {
    return a.unconverged_steps <= unconverged_steps_limit * a.averaged_steps;
  }

  TimeAverageVerdict time_average_verdict(const TimeAverage &a, double uncertainty_limit)
  {
    using Kind = TimeAverageVerdict::Kind;
    if (!steps_converged(a))
      return {Kind::steps_not_solved,
              std::to_string(a.unconverged_steps) + " of its " + std::to_string(a.averaged_steps) +
                " averaged time steps stopped at the step's iteration cap short of its tolerance (held by " +
                capped_steps_held_by(a) + "), more than " + format_number(100 * unconverged_steps_limit) +
                " % at Courant number " + format_number(a.courant_number) + " (after " +
                std::to_string(a.courant_halvings) +
                " halvings): the mean is not that of the marched equations (more `Pilot stage/Time average/Step "
                "halvings' or `Step iterations')"};
    if (!window_spans_motion(a))
      return {Kind::window_too_short,
              "its " + std::to_string(a.averaged_steps) +
                " averaged time steps do not span its flow's motion (the autocorrelation of C_d or the force "
                "falls to zero only after " +
                std::to_string(a.decorrelation_steps) + " steps; " + std::to_string(lags_per_window) +
                " times that are needed for its uncertainty to hold) within `Pilot stage/Time average/Steps limit'"};
    const double C_d_error = a.discharge_coefficient_relative_uncertainty;
    const double force_error = a.flapper_force_relative_uncertainty;
    if (!(C_d_error <= uncertainty_limit && force_error <= uncertainty_limit))
      return {Kind::mean_uncertain,
              "the mean of its time average is uncertain by " + format_number(100 * C_d_error) + " % in C_d and " +
                format_number(100 * force_error) +
                " % in the flapper force (standard errors), beyond `Pilot stage/Time average/Uncertainty limit' (" +
                format_number(100 * uncertainty_limit) + " %) after " +
                std::to_string(std::lround(a.averaged_time / a.time_step)) +
                " averaged steps, what `Pilot stage/Time average/Steps limit' allows"};
    return {Kind::stands, ""};
  }

  std::string capped_steps_held_by(const TimeAverage &a)
  {
    std::array<unsigned int, 5> order{0, 1, 2, 3, 4};
    std::stable_sort(order.begin(), order.end(), [&](unsigned int i, unsigned int j) {
      return a.unconverged_steps_held_by[i] > a.unconverged_steps_held_by[j];
    });
    std::string list;
    for (unsigned int i : order)
      if (a.unconverged_steps_held_by[i] > 0)
        list += (list.empty() ? "" : ", ") + std::string(residual_names[i]) + " in " +
                std::to_string(a.unconverged_steps_held_by[i]);
    return list;
  }

  AveragingPlan::AveragingPlan(unsigned int first, double averaged_fraction, unsigned int most, double limit_)
    : transient_steps(first - std::max(2u, std::min(first, static_cast<unsigned int>(std::lround(averaged_fraction * first)))))
    , planned_steps(first)
    , most_steps(std::max(first, most))
    , limit(limit_)
  {}

  bool AveragingPlan::lengthen(double error, unsigned int steps_needed)
  {
    const bool pinned = error <= limit, spanned = averaged() >= steps_needed;
    if ((pinned && spanned) || planned_steps >= most_steps)
      return false;
    double asked = 0;
    if (!pinned)
      {
        const double ratio = limit > 0 ? error / limit : std::numeric_limits<double>::infinity();
        asked = 1.1 * std::min(std::max(ratio * ratio, 1.0), 1e9) * averaged();
      }
    // a window that does not span the motion: its error estimate does not hold yet, whatever it says
    if (!spanned)
      asked = std::max(asked, 1.1 * steps_needed);
    // (less a millionth of a step: 1.1 x 4 x 200 is 880 and a rounding error, not 881)
    planned_steps = static_cast<unsigned int>(std::min<double>(most_steps, transient_steps + std::ceil(asked - 1e-6)));
    return true;
  }

  namespace
  {
    /// One march at the time step of `courant' from the field's current state: time_average's
    /// plan, its statistics and its gate on capped steps.
    TimeAverage march(PilotField &field, double dp, const PilotTimeAverageParameters &settings, double courant,
                      const std::function<void(unsigned int, unsigned int, double, const PilotFieldResult &)> &each_step)
    {
      TimeAverage a;
      a.courant_number = courant;
      a.time_step = field.courant_time_step(courant);
      AveragingPlan plan(settings.steps, settings.averaged_fraction, settings.steps_limit,
                         settings.uncertainty_limit);
      const bool has_flapper = field.geometry() == PilotGeometry::nozzle_flapper;
      RunningMoments Q, C_d, Re, force, land, jet, bore;
      std::vector<double> C_d_series, force_series; // over the averaged steps, for the standard errors
      RunningFields fields;
      PilotFieldResult &m = a.mean;
      // the window's spreads, means and decorrelation lag into a; returns the averaged steps its
      // motion needs (0: spanned)
      auto motion = [&] {
        a.discharge_coefficient_spread = C_d.standard_deviation();
        a.flapper_force_spread = force.standard_deviation();
        m.discharge_coefficient = C_d.mean, m.flapper_force = force.mean;
        a.decorrelation_steps = static_cast<unsigned int>(
          std::max(decorrelation_lag(C_d_series), has_flapper ? decorrelation_lag(force_series) : std::size_t(0)));
        a.averaged_steps = plan.averaged();
        return window_spans_motion(a) ? 0u : lags_per_window * a.decorrelation_steps;
      };
      auto relative_errors = [&] {
        a.discharge_coefficient_uncertainty = batch_means_standard_error(C_d_series, mean_batches);
        a.flapper_force_uncertainty = batch_means_standard_error(force_series, mean_batches);
        a.discharge_coefficient_relative_uncertainty = a.discharge_coefficient_uncertainty / std::abs(C_d.mean);
        a.flapper_force_relative_uncertainty = has_flapper ? a.flapper_force_uncertainty / std::abs(force.mean) : 0.0;
        return std::max(a.discharge_coefficient_relative_uncertainty, a.flapper_force_relative_uncertainty);
      };
      for (unsigned int step = 0; step < plan.planned(); ++step)
        {
          const PilotFieldResult r = field.advance(dp, a.time_step, settings.step_iterations, step_tolerance);
          m.iterations += r.iterations;
          if (each_step)
            each_step(step + 1, plan.planned(), (step + 1) * a.time_step, r);
          if (!plan.averages(step))
            continue;
          if (!r.step_converged)
            ++a.unconverged_steps, ++a.unconverged_steps_held_by[largest_residual_index(r.residuals)];
          Q.add(r.flow_rate), C_d.add(r.discharge_coefficient), Re.add(r.reynolds_number);
          force.add(r.flapper_force), land.add(r.land_force), jet.add(r.jet_force), bore.add(r.bore_pressure);
          C_d_series.push_back(r.discharge_coefficient), force_series.push_back(r.flapper_force);
          fields.add(field.fields());
          const bool start = Q.count == 1;
          m.minimum_pressure = start ? r.minimum_pressure : std::min(m.minimum_pressure, r.minimum_pressure);
          m.minimum_absolute_pressure =
            start ? r.minimum_absolute_pressure : std::min(m.minimum_absolute_pressure, r.minimum_absolute_pressure);
          m.cavitating = m.cavitating || r.cavitating;
          m.max_wall_y_plus = std::max(m.max_wall_y_plus, r.max_wall_y_plus);
          m.pressure_difference = r.pressure_difference, m.turbulence = r.turbulence;
          // at the end of the plan: a mean not yet pinned down gets the averaged time it asks for,
          // unless the gate on capped steps refuses it already (more steps would only add to a mean
          // that is not used; the capped fraction of a stationary run does not fall with its length)
          if (plan.at_end(step))
            {
              const unsigned int steps_needed = motion();
              if (steps_converged(a))
                plan.lengthen(relative_errors(), steps_needed);
            }
        }
      m.flow_rate = Q.mean, m.discharge_coefficient = C_d.mean, m.reynolds_number = Re.mean;
      m.flapper_force = force.mean, m.land_force = land.mean, m.jet_force = jet.mean, m.bore_pressure = bore.mean;
      motion();
      relative_errors();
      a.averaged_time = a.averaged_steps * a.time_step;
      a.mean_fields = fields.result();
      return a;
    }
  } // namespace

  TimeAverage time_average(PilotField &field, double dp, const PilotTimeAverageParameters &settings,
                           const std::function<void(unsigned int, unsigned int, double, const PilotFieldResult &)> &each_step,
                           const std::function<void(const TimeAverage &rejected)> &before_halving)
  {
    double courant = settings.courant_number;
    unsigned int iterations = 0, halvings = 0;
    for (;; courant /= 2, ++halvings)
      {
        TimeAverage a = march(field, dp, settings, courant, each_step);
        iterations += a.mean.iterations;
        a.mean.iterations = iterations;
        a.courant_halvings = halvings;
        if (steps_converged(a) || halvings == settings.step_halvings)
          return a;
        if (before_halving)
          before_halving(a);
      }
  }
} // namespace servodrift::flow
