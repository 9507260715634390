#include "system/steady_state_check.h"

#include "common/error.h"
#include "common/units.h"
#include "system/step_response.h"

#include <algorithm>

namespace servodrift::system
{
  ValveState rest_state(const ValveEquations &eq)
  {
    ValveState s;
    s.left_pressure = s.right_pressure = s.brake_pressure = eq.return_pressure();
    return s;
  }

  SteadyStateCheck steady_state_check(const ValveModel &model, const ValveDynamics &dynamics, double command,
                                      const DynamicsParameters &p)
  {
    const ValveEquations &eq = dynamics.equations();
    const std::string where = " at " + format_number(eq.temperature()) + " degC";
    const std::vector<double> point = dynamics.vector_of(model.solve(eq, dynamics.steady_current(command)).state());
    SteadyStateCheck c;
    c.duration = step_duration(model, dynamics, command, p);

    // from the static point: every internal step stays within rounding of it
    const auto stay = dynamics.integrator([command](double) { return command; }, p, "steady-state check" + where, point);
    stay->start(0.0, point);
    stay->integrate(c.duration, [&](double, double) {
      c.drift_from_static = std::max(c.drift_from_static, dynamics.scaled_distance(stay->y(), point));
      return true;
    });

    // from rest: in chunks of the step duration until a chunk changes the state by < 1e-10
    const auto start = dynamics.integrator([command](double) { return command; }, p, "start-up from rest" + where, point);
    start->start(0.0, dynamics.vector_of(rest_state(eq)));
    std::vector<double> previous = start->y();
    for (int chunk = 1; chunk <= 40; ++chunk)
      {
        const std::vector<double> y = start->advance_to(chunk * c.duration);
        const double change = dynamics.scaled_distance(y, previous);
        previous = y;
        c.settling_from_rest = start->time();
        if (change < 1e-10)
          break;
      }
    c.distance_from_rest = dynamics.scaled_distance(previous, point);
    return c;
  }
} // namespace servodrift::system
