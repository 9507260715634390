#pragma once
// Scalar root finding for the monotone equations of the static valve model (bridge pressures,
// torque balance, spool balance). TOMS 748 (Alefeld, Potra, Shi) from Boost.Math: bracketing, so it
// cannot leave the physical interval, and superlinear, so a root costs about ten evaluations.
#include <functional>

namespace servodrift
{
  /// Root of a continuous f on [a, b], given f(a) and f(b) of opposite sign (or one of them zero).
  /// Stops when the bracket is narrower than x_tolerance. Throws std::runtime_error (naming `what')
  /// if the signs do not bracket a root or the iteration limit is reached.
  double find_root(const std::function<double(double)> &f, double a, double b, double fa, double fb,
                   double x_tolerance, const char *what);
} // namespace servodrift
