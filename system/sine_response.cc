#include "system/sine_response.h"

#include "common/error.h"
#include "common/units.h"

#include <unsupported/Eigen/MatrixFunctions>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace servodrift::system
{
  namespace
  {
    using complex = std::complex<double>;

    /// (2/N) sum y_n exp(-j w t_n): the phasor P of the component Re(P exp(j w t)) of samples taken
    /// at N equally spaced times over whole periods of w.
    complex phasor(const std::vector<double> &y, const std::vector<double> &t, double w)
    {
      complex sum = 0;
      for (std::size_t n = 0; n < y.size(); ++n)
        sum += y[n] * std::exp(complex(0, -w * t[n]));
      return 2.0 / double(y.size()) * sum;
    }

    struct Period
    {
      std::array<std::vector<double>, 3> samples; ///< p_B, x_v, x_f = r theta
      std::vector<double> times;
    };

    /// Newton's method on x = P(x), where P takes the state at input phase 0 one period on: the
    /// shooting method for a periodic orbit (Aprille and Trick 1972). Unlike waiting for the
    /// transient, or extrapolating successive periods, it needs no mode to decay within a period: a
    /// valve whose slowest mode lasts thousands of periods (RV-1's spool and brake volume at -55
    /// degC, 5.5 s, at 1 kHz) takes the steps it takes at 40 degC. I - M, M = dP/dx, is made by
    /// difference quotients and kept while the steps it gives contract (chord steps), each of which
    /// then costs no more than the periods it is checked on.
    class Shooting
    {
    public:
      /// I - M first from the linearisation at the bias, M = exp(A T) in the states' scales: exact
      /// for a small amplitude, and it costs no period
      /// Without `enabled', no step at all
      explicit Shooting(bool enabled)
        : allowed_linearisations(enabled ? linearisation_limit : 0)
      {
      }

      void use_linearisation(const Linearisation &l, double period)
      {
        const Eigen::VectorXd s = Eigen::Map<const Eigen::VectorXd>(l.scales.data(), Eigen::Index(l.scales.size()));
        const Eigen::MatrixXd A_T = s.cwiseInverse().asDiagonal() * l.A * s.asDiagonal() * period;
        lu.compute(Eigen::MatrixXd::Identity(A_T.rows(), A_T.cols()) - A_T.exp());
        have_matrix = true;
      }

      /// I - M at x, whose columns take one period from x + h_j e_j each; h_j = sqrt(atol) of the
      /// state's scale: large against the integration's error (atol of the scale), small against
      /// the orbit. Returns P(x), from the same start as the columns; the integrator is left there.
      std::vector<double> linearise(ValveIntegrator &integrator, const ValveDynamics &d, double t0, double period,
                                    const std::vector<double> &x, double absolute_tolerance)
      {
        const std::size_t n = x.size();
        const auto one_period = [&](const std::vector<double> &from) {
          integrator.start(t0, from);
          return integrator.advance_to(t0 + period);
        };
        const double h = std::sqrt(absolute_tolerance);
        Eigen::MatrixXd I_minus_M = Eigen::MatrixXd::Identity(n, n); // of the scaled states y_k/scale_k
        const std::vector<double> Px = one_period(x);
        for (std::size_t j = 0; j < n; ++j)
          {
            std::vector<double> xj = x;
            xj[j] += h * d.scales()[j];
            const std::vector<double> Pxj = one_period(xj);
            for (std::size_t k = 0; k < n; ++k)
              I_minus_M(k, j) -= (Pxj[k] - Px[k]) / d.scales()[k] / h;
          }
        lu.compute(I_minus_M);
        have_matrix = true;
        ++linearisations;
        return Px;
      }

      /// x + (I - M)^-1 (P(x) - x); empty before linearise(), where I - M is singular (a mode that
      /// neither grows nor decays) or the step is not finite.
      std::optional<std::vector<double>> step(const ValveDynamics &d, const std::vector<double> &x,
                                              const std::vector<double> &Px) const
      {
        if (!have_matrix || !lu.isInvertible())
          return std::nullopt;
        Eigen::VectorXd residual(static_cast<Eigen::Index>(x.size()));
        for (std::size_t k = 0; k < x.size(); ++k)
          residual(static_cast<Eigen::Index>(k)) = (Px[k] - x[k]) / d.scales()[k];
        const Eigen::VectorXd dx = lu.solve(residual);
        std::vector<double> next = x;
        for (std::size_t k = 0; k < x.size(); ++k)
          next[k] += dx(static_cast<Eigen::Index>(k)) * d.scales()[k];
        if (!std::all_of(next.begin(), next.end(), [](double v) { return std::isfinite(v); }))
          return std::nullopt;
        return next;
      }

      unsigned int linearisations = 0;
      /// Past which a response that still is not periodic is left to its time integration: a
      /// fourth I - M that gives no contracting step means the response is far from smooth
      /// (contacts, a quasi-periodic motion), where Newton's method has nothing to offer.
      static constexpr unsigned int linearisation_limit = 4;
      const unsigned int allowed_linearisations;

    private:
      Eigen::FullPivLU<Eigen::MatrixXd> lu;
      bool have_matrix = false;
    };

    /// Distance from x to the nearest of the edges
    double clearance(double x, std::initializer_list<double> edges)
    {
      double d = std::numeric_limits<double>::infinity();
      for (double e : edges)
        d = std::min(d, std::abs(x - e));
      return d;
    }
  } // namespace

  double linear_amplitude(const ValveDynamics &dynamics, const Linearisation &l, const ValveState &bias_point, double f,
                          double largest, double margin)
  {
    const ValveEquations &eq = dynamics.equations();
    const double x_ov = eq.overlap(), stroke = eq.stroke_limit(), x0 = eq.null_gap();
    const double spool_room = margin * clearance(bias_point.spool_displacement, {-stroke, -x_ov, x_ov, stroke});
    const double flapper_room = margin * clearance(eq.flapper_displacement(bias_point.angle), {-x0, x0});
    const double spool = std::abs(transfer(l, Output::spool_displacement, f));
    const double flapper = std::abs(transfer(l, Output::flapper_displacement, f));
    return std::min({largest, spool_room / spool, flapper_room / flapper});
  }

  SineCheck sine_check(const ValveDynamics &dynamics, const Linearisation &l, const ValveState &bias_point, double bias,
                       double f, double largest, const DynamicsParameters &p)
  {
    SineCheck c;
    c.frequency = f;
    for (std::size_t k = 0; k < 3; ++k)
      {
        c.linear[k] = transfer(l, sine_outputs[k], f);
        c.dc_gain[k] = transfer(l, sine_outputs[k], 0.0);
      }
    double a = linear_amplitude(dynamics, l, bias_point, f, largest, p.linearity_margin);
    c.halvings.push_back(sine_response(dynamics, l, bias_point, bias, f, a, p));
    using limits = SineCheckLimits;
    for (unsigned int k = 0; k < limits::halvings && !c.linear_limit; ++k)
      {
        a /= 2;
        c.halvings.push_back(sine_response(dynamics, l, bias_point, bias, f, a, p));
        const std::complex<double> move = c.last_halving();
        c.linear_limit = c.halvings.back().periodic && c.halvings[c.halvings.size() - 2].periodic &&
                         std::abs(20 * std::log10(std::abs(move))) <= limits::halving_fraction * limits::decibel &&
                         std::abs(std::arg(move)) / units::degree <= limits::halving_fraction * limits::degree;
      }
    return c;
  }

  namespace
  {
    /// The response, with or without shooting steps (see sine_response)
    SineResponse integrated_response(const ValveDynamics &dynamics, const Linearisation &l,
                                     const ValveState &bias_point, double bias, double f, double a,
                                     const DynamicsParameters &p, const std::vector<double> *start, bool shoot)
    {
      const ValveEquations &eq = dynamics.equations();
      SineResponse r;
      r.frequency = f;
      r.amplitude = a;
      const double w = 2 * units::pi * f, period = 1 / f;
      // Start on the linear periodic solution (for a sin(w t) = Im(a exp(j w t)), y = Im(a X exp(j w t)))
      // where it stays within half the distance to the edges; a larger amplitude starts at the bias
      // point, since its linear solution may lie beyond the nozzles.
      std::vector<double> y0 = start ? *start : dynamics.vector_of(bias_point);
      const bool within_linear_range = a <= linear_amplitude(dynamics, l, bias_point, f, a, 0.5);
      if (!start && within_linear_range)
        {
          const Eigen::VectorXcd X = state_response(l, f);
          for (std::size_t k = 0; k < y0.size(); ++k)
            y0[k] += a * X(static_cast<Eigen::Index>(k)).imag();
        }

      const auto integrator = dynamics.integrator([=](double t) { return bias + a * std::sin(w * t); }, p,
                                                  "sine response at " + format_number(eq.temperature()) + " degC, " +
                                                      format_number(f) + " Hz",
                                                  dynamics.vector_of(bias_point));
      integrator->start(0.0, y0);
      eq.forget_table_excursions();

      const unsigned int N = p.samples_per_period;
      const double r_pivot = eq.pivot_to_nozzle_distance();
      const std::array<double, 3> scales = {eq.supply_pressure() - eq.return_pressure(), eq.stroke_limit(),
                                            eq.null_gap()};
      std::vector<Period> periods;                     // every whole period
      std::vector<std::vector<double>> boundaries{y0}; // the state at the start of each period
      std::size_t segment_start = 0;                   // first boundary since the last restart
      Period current;
      std::size_t period_index = 0;              // of the period being sampled, which starts at period_index / f
      const auto motion = [&](const Period &q) { // of the outputs over a period, in their scales
        double m = 0;
        for (std::size_t k = 0; k < 3; ++k)
          m = std::max(m, (*std::max_element(q.samples[k].begin(), q.samples[k].end()) -
                           *std::min_element(q.samples[k].begin(), q.samples[k].end())) /
                              scales[k]);
        return std::max(m, 1e-300);
      };

      const unsigned int most_periods = p.maximum_periods;
      // The bias linearisation's I - M describes the orbit only within the linear range
      Shooting shooting(shoot);
      if (shoot && within_linear_range)
        shooting.use_linearisation(l, period);
      double last_residual = std::numeric_limits<double>::infinity(); // of the last shooting step
      unsigned int shooting_steps = 0;
      bool relinearise = false;
      // restarts at the period start just reached, from x: a shooting step's state
      const auto restart_from = [&](const std::vector<double> &x) {
        ++shooting_steps;
        boundaries.back() = x;
        segment_start = boundaries.size() - 1;
        integrator->start(double(period_index) * period, x);
      };
      // An integration that fails (CVODE's steps run out, the state leaves the tables) ends the
      // response: not periodic, with the reason; the run goes on.
      try
        {
          for (bool restart = true; restart;)
            {
              integrator->integrate(most_periods * period, [&](double, double t) {
                // samples j = 0 .. N-1 at (period_index + j/N)/f; the state at j = N, the period's end, is the
                // next period's boundary
                for (double ts; (ts = (double(period_index) + double(current.times.size()) / N) * period) <= t;)
                  {
                    const std::vector<double> y = ts == t ? integrator->y() : integrator->interpolate(ts);
                    if (current.times.size() < N)
                      {
                        const std::array<double, 3> v = {y[6], y[4], r_pivot * y[0]};
                        for (std::size_t k = 0; k < 3; ++k)
                          current.samples[k].push_back(v[k]);
                        current.times.push_back(ts);
                        continue;
                      }
                    ++period_index;
                    boundaries.push_back(y);
                    periods.push_back(std::move(current));
                    current = Period{};
                    ++r.periods;
                    const std::size_t k = boundaries.size() - 1;
                    // Periodic with m periods: the state recurs after m periods, and did one period earlier.
                    // A sub-harmonic (m > 1) also needs successive periods that clearly differ (ten times the
                    // tolerance), or a transient that decays with an alternating sign would pass for one.
                    // Each output's samples must recur too, within the tolerance of that output's own range (at
                    // least 1e-4 of its scale: 2 kPa of p_B, 40 nm of x_v, 4 nm of x_f): a slow transient
                    // (RV-1's pressure loop decays over 150 periods at 2 kHz) can hide in the state's distance
                    // when the drive moves the flapper far more than it moves p_B.
                    const double scale = motion(periods.back());
                    const auto recurs = [&](std::size_t j, unsigned int m, double tolerance) {
                      return dynamics.scaled_distance(boundaries[j], boundaries[j - m]) <= tolerance * scale;
                    };
                    const auto outputs_recur = [&](unsigned int m) {
                      const Period &now = periods[k - 1], &then = periods[k - 1 - m];
                      for (std::size_t o = 0; o < 3; ++o)
                        {
                          const auto [lo, hi] = std::minmax_element(now.samples[o].begin(), now.samples[o].end());
                          const double range = std::max(*hi - *lo, 1e-4 * scales[o]);
                          for (std::size_t n = 0; n < N; ++n)
                            if (std::abs(now.samples[o][n] - then.samples[o][n]) > p.periodic_tolerance * range)
                              return false;
                        }
                      return true;
                    };
                    for (unsigned int m = 1; m <= 32 && k >= segment_start + m + 1; ++m)
                      if (recurs(k, m, p.periodic_tolerance) && recurs(k - 1, m, p.periodic_tolerance) &&
                          outputs_recur(m) &&
                          (m == 1 ||
                           (!recurs(k, 1, 10 * p.periodic_tolerance) && !recurs(k - 1, 1, 10 * p.periodic_tolerance))))
                        {
                          r.periodic = true;
                          r.response_periods = m;
                          return false;
                        }
                    r.last_change = dynamics.scaled_distance(boundaries[k], boundaries[k - 1]) / scale;
                    // Not periodic yet. A shooting step where the transient, at its rate over the
                    // last period, would take longer than the step costs: a chord step (a restart and
                    // the periods that check it) while they contract, else a new I - M (a period per
                    // state more).
                    if (k < segment_start + 3) // the first period after a restart has its own transient
                      continue;
                    const double residual = dynamics.scaled_distance(boundaries[k], boundaries[k - 1]);
                    const double rate = residual / dynamics.scaled_distance(boundaries[k - 1], boundaries[k - 2]);
                    const double periods_to_go =
                      rate < 1 ? std::log(p.periodic_tolerance * scale / residual) / std::log(rate) : HUGE_VAL;
                    if (periods_to_go <= 3)
                      continue;
                    if (residual < 0.5 * last_residual)
                      if (auto next = shooting.step(dynamics, boundaries[k - 1], boundaries[k]))
                        {
                          last_residual = residual;
                          restart_from(*next);
                          return false;
                        }
                    if (periods_to_go > double(boundaries.back().size() + 3) &&
                        shooting.linearisations < shooting.allowed_linearisations)
                      {
                        relinearise = true;
                        return false;
                      }
                  }
                return true;
              });
              if (relinearise)
                {
                  relinearise = false;
                  const std::vector<double> x = boundaries.back();
                  const std::vector<double> Px = shooting.linearise(
                      *integrator, dynamics, double(period_index) * period, period, x, p.absolute_tolerance);
                  last_residual = dynamics.scaled_distance(Px, x);
                  restart_from(shooting.step(dynamics, x, Px).value_or(x));
                }
              restart = !r.periodic && r.periods < most_periods;
            }
        }
      catch (const std::runtime_error &e)
        {
          r.periodic = false;
          r.failure = e.what();
        }
      r.shooting_steps = shooting_steps;
      if (periods.empty())
        return r;

      // The harmonics over the response's own period (m periods of the input), or, if it did not
      // become periodic, over the last (up to) eight periods since the last restart.
      const std::size_t available = std::min<std::size_t>(periods.size(), boundaries.size() - 1 - segment_start);
      const std::size_t window =
          r.periodic ? r.response_periods : std::min<std::size_t>(8, std::max<std::size_t>(1, available));
      std::array<std::vector<double>, 3> y;
      std::vector<double> times;
      for (std::size_t q = periods.size() - window; q < periods.size(); ++q)
        {
          for (std::size_t k = 0; k < 3; ++k)
            y[k].insert(y[k].end(), periods[q].samples[k].begin(), periods[q].samples[k].end());
          times.insert(times.end(), periods[q].times.begin(), periods[q].times.end());
        }
      const complex input_phasor(0, -a); // a sin(w t) = Re(-j a exp(j w t))
      std::array<complex, 3> first;
      for (std::size_t k = 0; k < 3; ++k)
        {
          first[k] = phasor(y[k], times, w);
          r.gain[k] = first[k] / input_phasor;
          r.minimum[k] = *std::min_element(y[k].begin(), y[k].end());
          r.maximum[k] = *std::max_element(y[k].begin(), y[k].end());
        }
      double higher = 0, lower = 0;
      for (unsigned int m = 2; m <= 10 && 2 * m < N; ++m)
        higher += std::norm(phasor(y[0], times, m * w));
      for (std::size_t j = 1; j < window; ++j) // the lines below f that the window resolves
        lower += std::norm(phasor(y[0], times, double(j) / double(window) * w));
      r.distortion = std::sqrt(higher) / std::abs(first[0]);
      r.subharmonic = std::sqrt(lower) / std::abs(first[0]);
      const double x0 = eq.null_gap(), x_ov = eq.overlap(), stroke = eq.stroke_limit();
      const double x_n = eq.offsets().hydraulic_null;
      r.flapper_contact = r.maximum[2] - x_n > x0 || r.minimum[2] - x_n < -x0;
      r.beyond_lap = r.maximum[1] > x_ov || r.minimum[1] < -x_ov;
      r.spool_on_stop = r.maximum[1] > stroke || r.minimum[1] < -stroke;
      r.left_tables = eq.left_tables();
      r.final_state = boundaries.back();
      return r;
    }
  } // namespace

  SineResponse sine_response(const ValveDynamics &dynamics, const Linearisation &l, const ValveState &bias_point,
                             double bias, double f, double a, const DynamicsParameters &p,
                             const std::vector<double> *start)
  {
    // Shooting steps first; where one of them led the integration astray (a state from which it
    // fails), the plain time integration from the same start
    SineResponse r = integrated_response(dynamics, l, bias_point, bias, f, a, p, start, true);
    if (!r.failure.empty() && r.shooting_steps > 0)
      r = integrated_response(dynamics, l, bias_point, bias, f, a, p, start, false);
    return r;
  }
} // namespace servodrift::system
