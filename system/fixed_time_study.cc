#include "system/fixed_time_study.h"

#include "common/error.h"
#include "common/sweep.h"
#include "common/units.h"
#include "system/steady_state_check.h"
#include "system/valve_dynamics.h"

#include <algorithm>
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

  FixedTimeStudy fixed_time_study(const ValveModel &model, double amplifier, OutputParameters::Progress progress)
  {
    const ValveDescription &valve = model.description();
    const auto &p = valve.dynamics;
    FixedTimeStudy study;
    study.temperatures = valve.sweeps.drift_temperatures;
    study.reading_times = p.reading_times;
    study.deviation_angle = valve.sweeps.deviation_angles.back();
    const double rated = valve.operating.rated_current;
    const std::size_t n_T = study.temperatures.size(), n_t = study.reading_times.size();

    // case (T, deviation, current): x_v and p_B at the reading times, then at the static point
    const std::array<double, 2> angles = {0.0, study.deviation_angle}, currents = {0.0, rated};
    const auto rows = run_sweep(
      "dynamics: fixed-time readings", n_T * 4,
      [&](std::size_t c) {
        const double T = study.temperatures[c / 4], angle = angles[(c / 2) % 2], command = currents[c % 2];
        const ValveDynamics dynamics(model.equations(T, model.offsets_for_deviation(angle)), amplifier, rated);
        const OperatingPoint end = model.solve(dynamics.equations(), dynamics.steady_current(command));
        const auto integrator =
          dynamics.integrator([command](double) { return command; }, p,
                              "fixed-time study at " + format_number(T) + " degC, theta_d = " +
                                format_number(angle / units::degree) + " deg, i = " + format_number(command) + " A",
                              dynamics.vector_of(end.state()));
        integrator->start(0.0, dynamics.vector_of(rest_state(dynamics.equations())));
        std::vector<double> row;
        for (double t : study.reading_times)
          {
            const auto &y = integrator->advance_to(t);
            row.push_back(command == 0 ? y[4] : y[6]);
          }
        row.push_back(command == 0 ? end.spool.displacement : end.spool.brake_pressure);
        return CaseRows{row};
      },
      progress);

    study.displacement_deviation.assign(n_t, std::vector<double>(n_T));
    study.pressure_deviation.assign(n_t, std::vector<double>(n_T));
    study.static_displacement_deviation.resize(n_T);
    study.static_pressure_deviation.resize(n_T);
    for (std::size_t k = 0; k < n_T; ++k)
      {
        const auto &x0 = rows[4 * k], &p0 = rows[4 * k + 1], &x1 = rows[4 * k + 2], &p1 = rows[4 * k + 3];
        for (std::size_t j = 0; j < n_t; ++j)
          {
            study.displacement_deviation[j][k] = x1[j] - x0[j];
            study.pressure_deviation[j][k] = p1[j] - p0[j];
          }
        study.static_displacement_deviation[k] = x1[n_t] - x0[n_t];
        study.static_pressure_deviation[k] = p1[n_t] - p0[n_t];
      }
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < n_t; ++j)
      {
        const auto rx = slope_ratio(study.temperatures, study.displacement_deviation[j]);
        const auto rp = slope_ratio(study.temperatures, study.pressure_deviation[j]);
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
    study.static_displacement_slope_ratio = slope_ratio(study.temperatures, study.static_displacement_deviation);
    study.static_pressure_slope_ratio = slope_ratio(study.temperatures, study.static_pressure_deviation);
    return study;
  }
} // namespace servodrift::system
