#include "magnetics/bh_curve.h"

#include "common/units.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace servodrift::magnetics
{
  using units::mu0;
  using units::pi;

  ArctanBHCurve::ArctanBHCurve(double saturation_polarisation, double initial_susceptibility)
    : J_s(saturation_polarisation)
    , chi0(initial_susceptibility)
    , c(pi * initial_susceptibility * units::mu0 / (2 * saturation_polarisation))
  {
    if (!(J_s > 0 && chi0 >= 0))
      throw std::invalid_argument("B-H curve: saturation polarisation must be > 0 and susceptibility >= 0");
    // H(B) is called at every quadrature point of every assembly: tabulate B(H) on a geometric grid
    // of H once. At a ratio of 1.002 the cubic Hermite interpolant in B is within 1e-12 of H(B)
    // (9.5e-13 at most over 1e-6..3 T), so the table is H(B) there, without a Newton correction and
    // its arctangent: 14 thousand entries.
    for (double H = 1e-3; H < 1e9; H *= 1.002)
      {
        table_H.push_back(H);
        table_B.push_back(flux_density(H));
        table_dHdB.push_back(1 / differential_permeability(H));
      }
  }

  double ArctanBHCurve::flux_density(double H) const
  {
    return mu0 * H + (2 * J_s / pi) * std::atan(c * H);
  }

  double ArctanBHCurve::differential_permeability(double H) const
  {
    return mu0 + (2 * J_s / pi) * c / (1 + c * c * H * H);
  }

  double ArctanBHCurve::field_strength(double B) const
  {
    if (B <= 0)
      return 0;
    const auto it = std::upper_bound(table_B.begin(), table_B.end(), B);
    if (it != table_B.begin() && it != table_B.end())
      {
        // cubic Hermite in B through (B_k, H_k) with slopes dH/dB: error O(dB^4), below 1e-12
        const std::size_t k = it - table_B.begin();
        const double h = table_B[k] - table_B[k - 1], t = (B - table_B[k - 1]) / h;
        const double t2 = t * t, t3 = t2 * t;
        return (2 * t3 - 3 * t2 + 1) * table_H[k - 1] + (t3 - 2 * t2 + t) * h * table_dHdB[k - 1] +
               (-2 * t3 + 3 * t2) * table_H[k] + (t3 - t2) * h * table_dHdB[k];
      }
    // Outside the table (below B(1e-3 A/m), 2.5e-5 T for 1J50, or in deep saturation) by Newton's
    // method. B(H) is increasing and concave for H >= 0, so it lies below its tangents: from any
    // start, the first Newton step lands at or below the root and the following ones climb to it
    // monotonically.
    double H = it == table_B.begin() ? B / (mu0 * (1 + chi0)) // below the table: the initial slope
                                     : (B - J_s) / mu0;         // beyond it: B <= mu0 H + J_s
    for (int k = 0; k < 100; ++k)
      {
        const double step = (B - flux_density(H)) / differential_permeability(H);
        H += step;
        if (std::abs(step) <= 1e-15 * H)
          break;
      }
    return H;
  }

  void ArctanBHCurve::reluctivities(double B, double &nu, double &nu_differential) const
  {
    if (B <= 1e-12)
      {
        nu = nu_differential = 1 / (mu0 * (1 + chi0)); // B -> 0: dB/dH = mu0 + (2 J_s/pi) c
        return;
      }
    const double H = field_strength(B);
    nu = H / B;
    nu_differential = 1 / differential_permeability(H);
  }

  double ArctanBHCurve::coenergy_density(double H) const
  {
    // int_0^H mu0 h + (2 J_s/pi) atan(c h) dh
    return 0.5 * mu0 * H * H + (2 * J_s / pi) * (H * std::atan(c * H) - std::log1p(c * c * H * H) / (2 * c));
  }
} // namespace servodrift::magnetics
