#include "system/fixed_time_study.h"

#include "common/error.h"
#include "common/sweep.h"
#include "common/units.h"
#include "system/steady_state_check.h"
#include "system/valve_dynamics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace servodrift::system
{
  std::optional<double> slope_ratio(const std::vector<double> &T, const std::vector<double> &d)
  {
    const auto at = [&](double temperature) -> std::optional<double> {
      const auto k = std::find(T.begin(), T.end(), temperature);
      return k == T.end() ? std::nullopt : std::optional<double>(d[k - T.begin()]);
    };
    const auto d40 = at(40), d50 = at(50), d110 = at(110), d120 = at(120);
    if (!d40 || !d50 || !d110 || !d120 || *d120 == *d110)
      return std::nullopt;
    return (*d50 - *d40) / (*d120 - *d110);
  }

  std::vector<FixedTimeStudy> fixed_time_study(const ValveModel &model, double amplifier,
                                               OutputParameters::Progress progress)
  {
    const ValveDescription &valve = model.description();
    const auto &p = valve.dynamics;
    const std::vector<double> &temperatures = valve.sweeps.drift_temperatures;
    std::vector<double> angles = {0.0};
    angles.insert(angles.end(), p.fixed_time_deviation_angles.begin(), p.fixed_time_deviation_angles.end());
    const double rated = valve.operating.rated_current;
    const std::size_t n_T = temperatures.size(), n_t = p.reading_times.size(), n_a = angles.size();
    const std::array<double, 2> currents = {0.0, rated};

    // case (T, deviation, current): x_v (i = 0) or p_B (rated) at the reading times, then at the static point
    const auto rows = run_sweep(
      "dynamics: fixed-time readings", n_T * n_a * 2,
      [&](std::size_t c) {
        const double T = temperatures[c / (2 * n_a)], angle = angles[(c / 2) % n_a], command = currents[c % 2];
        const ValveDynamics dynamics(model.equations(T, model.offsets_for_deviation(angle)), amplifier, rated);
        const OperatingPoint end = model.solve(dynamics.equations(), dynamics.steady_current(command));
        const auto integrator =
          dynamics.integrator([command](double) { return command; }, p,
                              "fixed-time study at " + format_number(T) + " degC, theta_d = " +
                                format_number(angle / units::degree) + " deg, i = " + format_number(command) + " A",
                              dynamics.vector_of(end.state()));
        integrator->start(0.0, dynamics.vector_of(rest_state(dynamics.equations())));
        std::vector<double> row;
        for (double t : p.reading_times)
          {
            const auto &y = integrator->advance_to(t);
            row.push_back(command == 0 ? y[4] : y[6]);
          }
        row.push_back(command == 0 ? end.spool.displacement : end.spool.brake_pressure);
        return CaseRows{row};
      },
      progress);
    const auto at = [&](std::size_t T, std::size_t a, std::size_t i) -> const std::vector<double> & {
      return rows[(T * n_a + a) * 2 + i];
    };

    std::vector<FixedTimeStudy> studies;
    for (std::size_t a = 1; a < n_a; ++a)
      {
        FixedTimeStudy study;
        study.temperatures = temperatures;
        study.reading_times = p.reading_times;
        study.deviation_angle = angles[a];
        study.displacement_deviation.assign(n_t, std::vector<double>(n_T));
        study.pressure_deviation.assign(n_t, std::vector<double>(n_T));
        study.static_displacement_deviation.resize(n_T);
        study.static_pressure_deviation.resize(n_T);
        for (std::size_t k = 0; k < n_T; ++k)
          for (std::size_t j = 0; j <= n_t; ++j)
            {
              const double dx = at(k, a, 0)[j] - at(k, 0, 0)[j], dp = at(k, a, 1)[j] - at(k, 0, 1)[j];
              if (j < n_t)
                {
                  study.displacement_deviation[j][k] = dx;
                  study.pressure_deviation[j][k] = dp;
                }
              else
                {
                  study.static_displacement_deviation[k] = dx;
                  study.static_pressure_deviation[k] = dp;
                }
            }
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j < n_t; ++j)
          {
            const auto rx = slope_ratio(temperatures, study.displacement_deviation[j]);
            const auto rp = slope_ratio(temperatures, study.pressure_deviation[j]);
            study.displacement_slope_ratio.push_back(rx);
            study.pressure_slope_ratio.push_back(rp);
            if (rx && rp && *rx > 0 && *rp > 0)
              if (const double miss = std::abs(std::log(*rx / paper_displacement_slope_ratio)) +
                                      std::abs(std::log(*rp / paper_pressure_slope_ratio));
                  miss < best)
                {
                  best = miss;
                  study.best = j;
                }
          }
        study.static_displacement_slope_ratio = slope_ratio(temperatures, study.static_displacement_deviation);
        study.static_pressure_slope_ratio = slope_ratio(temperatures, study.static_pressure_deviation);
        studies.push_back(std::move(study));
      }
    return studies;
  }
} // namespace servodrift::system
