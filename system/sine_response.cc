#include "system/sine_response.h"

#include "common/error.h"
#include "common/units.h"

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

    /// Reduced rank extrapolation of the states x_0..x_q of a fixed-point iteration (here: the
    /// state at the start of successive periods) to its limit: the combination sum g_i x_i with
    /// sum g_i = 1 that makes the combined differences sum g_i (x_(i+1) - x_i) smallest, in the
    /// states' scales. Exact for a linear map with at most q - 1 slow modes. Empty if ill-posed.
    std::optional<std::vector<double>> extrapolate(const ValveDynamics &d, const std::vector<std::vector<double>> &x)
    {
      const std::size_t q = x.size() - 1, n = x.front().size();
      Eigen::MatrixXd U(n, q);
      for (std::size_t i = 0; i < q; ++i)
        for (std::size_t k = 0; k < n; ++k)
          U(k, i) = (x[i + 1][k] - x[i][k]) / d.scales()[k];
      // g_0 = 1 - sum c_i: minimise |u_0 + sum_i c_i (u_i - u_0)|
      Eigen::MatrixXd D(n, q - 1);
      for (std::size_t i = 1; i < q; ++i)
        D.col(i - 1) = U.col(i) - U.col(0);
      // A slow mode's differences turn little from period to period (0.16 rad per period for RV-1's
      // 50 Hz pressure loop at 2 kHz): nearly parallel columns, which Eigen's default threshold would
      // call dependent; only true dependence is refused.
      Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr;
      qr.setThreshold(1e-13);
      qr.compute(D);
      if (qr.rank() < static_cast<Eigen::Index>(q - 1))
        return std::nullopt;
      const Eigen::VectorXd c = qr.solve(-U.col(0));
      std::vector<double> limit(n, 0.0);
      for (std::size_t i = 0; i < q; ++i)
        {
          const double g = i == 0 ? 1 - c.sum() : c(i - 1);
          for (std::size_t k = 0; k < n; ++k)
            limit[k] += g * x[i + 1][k];
        }
      for (double v : limit)
        if (!std::isfinite(v))
          return std::nullopt;
      return limit;
    }

    /// Distance from x to the nearest of the edges
    double clearance(double x, std::initializer_list<double> edges)
    {
      double d = std::numeric_limits<double>::infinity();
      for (double e : edges)
        d = std::min(d, std::abs(x - e));
      return d;
    }
  } // namespace

  double linear_amplitude(const ValveDynamics &dynamics, const Linearisation &l, const ValveState &bias_point,
                          double f, double largest, double margin)
  {
    const ValveEquations &eq = dynamics.equations();
    const double x_ov = eq.overlap(), stroke = eq.stroke_limit(), x0 = eq.null_gap();
    const double spool_room =
      margin * clearance(bias_point.spool_displacement, {-stroke, -x_ov, x_ov, stroke});
    const double flapper_room = margin * clearance(eq.flapper_displacement(bias_point.angle), {-x0, x0});
    const double spool = std::abs(transfer(l, Output::spool_displacement, f));
    const double flapper = std::abs(transfer(l, Output::flapper_displacement, f));
    return std::min({largest, spool_room / spool, flapper_room / flapper});
  }

  SineCheck sine_check(const ValveDynamics &dynamics, const Linearisation &l, const ValveState &bias_point,
                       double bias, double f, double largest, const DynamicsParameters &p)
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

  SineResponse sine_response(const ValveDynamics &dynamics, const Linearisation &l, const ValveState &bias_point,
                             double bias, double f, double a, const DynamicsParameters &p,
                             const std::vector<double> *start)
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
    if (!start && a <= linear_amplitude(dynamics, l, bias_point, f, a, 0.5))
      {
        const Eigen::VectorXcd X = state_response(l, f);
        for (std::size_t k = 0; k < y0.size(); ++k)
          y0[k] += a * X(static_cast<Eigen::Index>(k)).imag();
      }

    const auto integrator =
      dynamics.integrator([=](double t) { return bias + a * std::sin(w * t); }, p,
                          "sine response at " + format_number(eq.temperature()) + " degC, " + format_number(f) + " Hz",
                          dynamics.vector_of(bias_point));
    integrator->start(0.0, y0);
    eq.forget_table_excursions();

    const unsigned int N = p.samples_per_period;
    const double r_pivot = eq.pivot_to_nozzle_distance();
    const std::array<double, 3> scales = {eq.supply_pressure() - eq.return_pressure(), eq.stroke_limit(), eq.null_gap()};
    std::vector<Period> periods;                  // every whole period
    std::vector<std::vector<double>> boundaries{y0}; // the state at the start of each period
    std::size_t segment_start = 0;                // first boundary since the last restart
    Period current;
    std::size_t period_index = 0; // of the period being sampled, which starts at period_index / f
    const auto motion = [&](const Period &q) { // of the outputs over a period, in their scales
      double m = 0;
      for (std::size_t k = 0; k < 3; ++k)
        m = std::max(m, (*std::max_element(q.samples[k].begin(), q.samples[k].end()) -
                         *std::min_element(q.samples[k].begin(), q.samples[k].end())) / scales[k]);
      return std::max(m, 1e-300);
    };

    bool restart = true;
    // at least `Maximum periods', and at least 4 time constants of the slowest mode: above the
    // valve's bandwidth the pressure loop's transient outlasts many periods (150 at 2 kHz for RV-1)
    const double slowest = slowest_decay_rate(l);
    const unsigned int most_periods = static_cast<unsigned int>(
      std::max<double>(p.maximum_periods, slowest > 0 ? std::min(1e6, std::ceil(4 / slowest / period)) : 0));
    while (restart && !r.periodic && r.periods < most_periods)
      {
        restart = false;
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
            if (recurs(k, m, p.periodic_tolerance) && recurs(k - 1, m, p.periodic_tolerance) && outputs_recur(m) &&
                (m == 1 || (!recurs(k, 1, 10 * p.periodic_tolerance) && !recurs(k - 1, 1, 10 * p.periodic_tolerance))))
              {
                r.periodic = true;
                r.response_periods = m;
                return false;
              }
          r.last_change = dynamics.scaled_distance(boundaries[k], boundaries[k - 1]) / scale;
          // Convergence to a one-period orbit is geometric, slow where the valve's slowest mode
          // decays over many periods: every fourth period, extrapolate the boundary states to their
          // limit (reduced rank extrapolation) and restart there.
          if (k >= segment_start + 4 && (k - segment_start) % 4 == 0 && r.extrapolations < 8)
            if (auto limit = extrapolate(dynamics, {boundaries.end() - 5, boundaries.end()}))
              {
                ++r.extrapolations;
                boundaries.back() = *limit;
                segment_start = k;
                integrator->start(double(period_index) * period, *limit);
                restart = true;
                return false; // continue from the extrapolated state
              }
        }
      return true;
    });
      }
    if (periods.empty())
      return r;

    // The harmonics over the response's own period (m periods of the input), or, if it did not
    // become periodic, over the last (up to) eight periods since the last restart.
    const std::size_t available = std::min<std::size_t>(periods.size(), boundaries.size() - 1 - segment_start);
    const std::size_t window = r.periodic ? r.response_periods : std::min<std::size_t>(8, std::max<std::size_t>(1, available));
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
} // namespace servodrift::system
