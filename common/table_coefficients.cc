#include "common/table_coefficients.h"

#include "common/units.h"

#include <algorithm>
#include <cmath>

namespace servodrift
{
  namespace
  {
    /// Smallest positive node of an axis that contains 0 (or the smallest |node| otherwise).
    double first_step(const std::vector<double> &axis)
    {
      double h = std::abs(axis.back() - axis.front());
      for (double x : axis)
        if (x != 0)
          h = std::min(h, std::abs(x));
      return h;
    }

    /// Richardson-extrapolated central difference: (4 D(h) - D(2h))/3, or D(h) if 2h leaves the range.
    double derivative(const std::function<double(double)> &f, double h, double limit)
    {
      const double d1 = (f(h) - f(-h)) / (2 * h);
      if (2 * h > limit)
        return d1;
      const double d2 = (f(2 * h) - f(-2 * h)) / (4 * h);
      return (4 * d1 - d2) / 3;
    }
  } // namespace

  TorqueMotorCoefficients torque_motor_coefficients(const GridFunction &torque, double T)
  {
    TorqueMotorCoefficients c;
    c.temperature = T;
    const double tenth = 0.1 * units::degree;
    c.torque_at_tenth_degree = torque(T, tenth, 0.0);
    c.secant_magnetic_spring = c.torque_at_tenth_degree / tenth; // C1
    const auto &angles = torque.axis(1), &currents = torque.axis(2);
    const double angle_limit = std::min(-angles.front(), angles.back());
    const double current_limit = std::min(-currents.front(), currents.back());
    c.magnetic_spring = derivative([&](double a) { return torque(T, a, 0.0); }, first_step(angles), angle_limit);
    c.torque_constant = derivative([&](double i) { return torque(T, 0.0, i); }, first_step(currents), current_limit);
    return c;
  }
} // namespace servodrift
