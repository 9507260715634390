#include "system/drift_map.h"

#include "common/sweep.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace servodrift::system
{
  std::vector<double> derivative_on_grid(const std::vector<double> &x, const std::vector<double> &y)
  {
    const std::size_t n = x.size();
    std::vector<double> d(n, 0.0);
    if (n < 2)
      return d;
    if (n == 2)
      {
        d[0] = d[1] = (y[1] - y[0]) / (x[1] - x[0]);
        return d;
      }
    // three-point Lagrange derivative at node j of the stencil (x[i-1], x[i], x[i+1])
    auto three_point = [&](std::size_t i, std::size_t j) {
      const double x0 = x[i - 1], x1 = x[i], x2 = x[i + 1], xj = x[j];
      return y[i - 1] * (2 * xj - x1 - x2) / ((x0 - x1) * (x0 - x2)) +
             y[i] * (2 * xj - x0 - x2) / ((x1 - x0) * (x1 - x2)) + y[i + 1] * (2 * xj - x0 - x1) / ((x2 - x0) * (x2 - x1));
    };
    d[0] = three_point(1, 0);
    for (std::size_t i = 1; i + 1 < n; ++i)
      d[i] = three_point(i, i);
    d[n - 1] = three_point(n - 2, n - 1);
    return d;
  }

  namespace
  {
    constexpr double none = std::numeric_limits<double>::quiet_NaN(); // internal marker only

    /// An operating point whose spool or flapper sits at a limit, or in another regime than its
    /// reference point's.
    bool saturated(const OperatingPoint &p, const OperatingPoint &reference)
    {
      const auto s = p.spool.state;
      return p.flapper != FlapperState::free || reference.flapper != FlapperState::free ||
             s == SpoolState::on_negative_stop || s == SpoolState::on_positive_stop || s != reference.spool.state;
    }

    std::vector<double> with_value(std::vector<double> list, double v)
    {
      if (std::find(list.begin(), list.end(), v) == list.end())
        {
          list.push_back(v);
          std::sort(list.begin(), list.end());
        }
      return list;
    }

    // The raw result of one case, packed into a row so that it travels through run_sweep.
    std::vector<double> pack(const DriftPoint &p)
    {
      auto op = [](const OperatingPoint &o) -> std::vector<double> {
        const auto &b = o.bridge;
        return {o.temperature, o.current, o.angle, o.flapper_displacement, b.left_gap, b.right_gap,
                b.left_pressure, b.right_pressure, b.left_flow, b.right_flow, b.left_force, b.right_force,
                o.spool.displacement, o.spool.brake_pressure, double(int(o.spool.state)), double(int(o.flapper))};
      };
      std::vector<double> r{p.temperature, p.deviation_angle, p.offsets.spring_tube_rest_angle, p.offsets.magnetic_null,
                            p.offsets.hydraulic_null, p.null_shift_current ? *p.null_shift_current : none};
      for (const auto *o : {&p.zero_current, &p.rated_current})
        {
          const auto v = op(*o);
          r.insert(r.end(), v.begin(), v.end());
        }
      return r;
    }

    DriftPoint unpack(const std::vector<double> &r)
    {
      DriftPoint p{};
      p.temperature = r[0];
      p.deviation_angle = r[1];
      p.offsets = {r[2], r[3], r[4], {}, {}};
      if (!std::isnan(r[5]))
        p.null_shift_current = r[5];
      std::size_t k = 6;
      for (auto *o : {&p.zero_current, &p.rated_current})
        {
          o->temperature = r[k++];
          o->current = r[k++];
          o->angle = r[k++];
          o->flapper_displacement = r[k++];
          auto &b = o->bridge;
          b.left_gap = r[k++];
          b.right_gap = r[k++];
          b.left_pressure = r[k++];
          b.right_pressure = r[k++];
          b.left_flow = r[k++];
          b.right_flow = r[k++];
          b.left_force = r[k++];
          b.right_force = r[k++];
          o->spool.displacement = r[k++];
          o->spool.brake_pressure = r[k++];
          o->spool.state = static_cast<SpoolState>(int(r[k++]));
          o->flapper = static_cast<FlapperState>(int(r[k++]));
        }
      return p;
    }
  } // namespace

  DriftMap compute_drift_map(const ValveModel &model, OutputParameters::Progress progress)
  {
    const auto &valve = model.description();
    const double T0 = valve.operating.reference_temperature, i_rated = valve.operating.rated_current;
    DriftMap map;
    map.temperatures = valve.sweeps.drift_temperatures;
    map.deviation_angles = valve.sweeps.deviation_angles;
    map.nulled_at_reference = valve.offsets.nulling == OffsetParameters::Nulling::nulled_at_reference;

    // The grid computed: the map plus what its deviations refer to (T0, theta_d = 0).
    const std::vector<double> temperatures = with_value(map.temperatures, T0);
    const std::vector<double> angles = with_value(map.deviation_angles, 0.0);
    const std::size_t n_a = angles.size();

    // Offsets depend on theta_d only (nulling happens at T0): compute them once per angle.
    std::vector<Offsets> offsets;
    for (double theta_d : angles)
      offsets.push_back(model.offsets_for_deviation(theta_d));

    const auto rows = run_sweep(
      "system: drift map", temperatures.size() * n_a,
      [&](std::size_t k) {
        DriftPoint p{};
        p.temperature = temperatures[k / n_a];
        p.deviation_angle = angles[k % n_a];
        p.offsets = offsets[k % n_a];
        p.zero_current = model.solve(p.temperature, 0.0, p.offsets);
        p.rated_current = model.solve(p.temperature, i_rated, p.offsets);
        p.null_shift_current = model.null_shift_current(p.temperature, p.offsets);
        return CaseRows{pack(p)};
      },
      progress);
    std::vector<DriftPoint> all;
    for (const auto &r : rows)
      all.push_back(unpack(r));
    const auto find = [&](double T, double a) -> const DriftPoint & {
      const std::size_t t = std::find(temperatures.begin(), temperatures.end(), T) - temperatures.begin();
      const std::size_t j = std::find(angles.begin(), angles.end(), a) - angles.begin();
      return all[t * n_a + j];
    };

    // Deviations (E40): relative to theta_d = 0 at the same T (as assembled) or to the same valve at
    // T0 (nulled at reference, D9).
    for (double T : map.temperatures)
      for (double a : map.deviation_angles)
        {
          DriftPoint p = find(T, a);
          const DriftPoint &ref = map.nulled_at_reference ? find(T0, a) : find(T, 0.0);
          p.spool_displacement_deviation = p.zero_current.spool.displacement - ref.zero_current.spool.displacement;
          p.brake_pressure_deviation = p.rated_current.spool.brake_pressure - ref.rated_current.spool.brake_pressure;
          // C8: remove the theta_d = 0 valve's own temperature drift (zero by construction as assembled)
          const double own = map.nulled_at_reference ? find(T, 0.0).rated_current.spool.brake_pressure -
                                                         find(T0, 0.0).rated_current.spool.brake_pressure :
                                                       0.0;
          p.brake_pressure_deviation_own_drift_removed = p.brake_pressure_deviation - own;
          p.null_pressure_shift = p.zero_current.control_pressure_difference();
          p.displacement_saturated = saturated(p.zero_current, ref.zero_current);
          p.pressure_saturated = saturated(p.rated_current, ref.rated_current);
          map.points.push_back(p);
        }

    // Tangent slopes d(delta)/dT along each deviation angle
    const std::size_t n_t = map.temperatures.size(), n_m = map.deviation_angles.size();
    for (std::size_t a = 0; a < n_m; ++a)
      {
        std::vector<double> dx(n_t), dp(n_t);
        for (std::size_t t = 0; t < n_t; ++t)
          {
            dx[t] = map.points[t * n_m + a].spool_displacement_deviation;
            dp[t] = map.points[t * n_m + a].brake_pressure_deviation;
          }
        const auto sx = derivative_on_grid(map.temperatures, dx), sp = derivative_on_grid(map.temperatures, dp);
        for (std::size_t t = 0; t < n_t; ++t)
          {
            map.points[t * n_m + a].spool_displacement_deviation_slope = sx[t];
            map.points[t * n_m + a].brake_pressure_deviation_slope = sp[t];
          }
      }
    return map;
  }
} // namespace servodrift::system
