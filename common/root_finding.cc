#include "common/root_finding.h"

#include "common/error.h"

#include <boost/math/tools/toms748_solve.hpp>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace servodrift
{
  double find_root(const std::function<double(double)> &f, double a, double b, double fa, double fb,
                   double x_tolerance, const char *what)
  {
    if (fa == 0)
      return a;
    if (fb == 0)
      return b;
    if ((fa > 0) == (fb > 0) || !std::isfinite(fa) || !std::isfinite(fb))
      throw std::runtime_error(std::string(what) + ": no root bracketed in [" + format_number(a) + ", " +
                               format_number(b) + "] (f = " + format_number(fa) + ", " + format_number(fb) + ")");
    std::uintmax_t max_iterations = 200;
    const auto tolerance = [x_tolerance](double lo, double hi) { return std::abs(hi - lo) <= x_tolerance; };
    const auto bracket = boost::math::tools::toms748_solve(f, a, b, fa, fb, tolerance, max_iterations);
    if (max_iterations >= 200)
      throw std::runtime_error(std::string(what) + ": root finding did not converge in 200 iterations");
    return 0.5 * (bracket.first + bracket.second);
  }
} // namespace servodrift
