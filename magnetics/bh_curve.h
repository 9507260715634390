#pragma once
// The 1J50 (Fe-50Ni) B-H law of model.md 2.2 for the field model:
//   B(H) = mu0 H + (2 J_s/pi) atan(pi chi0 mu0 H/(2 J_s)),
// with what the A_z formulation needs: H(B) (inverted by Newton), the reluctivity nu = H/B, the
// differential reluctivity dH/dB for the Newton Jacobian, and the coenergy density for virtual work.
#include <vector>

namespace servodrift::magnetics
{
  class ArctanBHCurve
  {
  public:
    ArctanBHCurve(double saturation_polarisation, double initial_susceptibility);

    double flux_density(double H) const;               ///< B(H) [T]
    double differential_permeability(double H) const;  ///< dB/dH [H/m]
    double field_strength(double B) const;              ///< H(B), B >= 0 [A/m]
    /// nu = H/B and nu_d = dH/dB at |B| = B (the B -> 0 limit at B = 0) [m/H]
    void reluctivities(double B, double &nu, double &nu_differential) const;
    /// w'(H) = int_0^H B dH' [J/m^3]
    double coenergy_density(double H) const;

  private:
    double J_s, chi0, c; // c = pi chi0 mu0/(2 J_s)
    /// Inverse table: H_k (geometric, ratio 1.002), B_k = B(H_k) and dH/dB at B_k, whose cubic
    /// Hermite interpolant is H(B) to 1e-12.
    std::vector<double> table_B, table_H, table_dHdB;
  };
} // namespace servodrift::magnetics
