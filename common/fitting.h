#pragma once
// Least-squares fits of polynomial surfaces in named variables (Eigen, column-pivoting Householder
// QR on variables scaled to [-1, 1]). Used for the paper's forms E25-E28 and for general full
// polynomials of given degrees; results go to tables/fits.json.
#include "common/json.h"

#include <string>
#include <vector>

namespace servodrift
{
  struct PolynomialFit
  {
    std::string name;        ///< e.g. "E25 magnetic spring K_m(T)"
    std::string source;      ///< table and column it was fitted to
    std::string response;    ///< response with unit, e.g. "K_m[N*m/rad]"
    std::vector<std::string> variables; ///< with units, e.g. "temperature[degC]"
    std::vector<std::vector<unsigned int>> exponents; ///< one exponent list per term
    std::vector<double> coefficients;        ///< physical: y = sum_k c_k prod_j x_j^e_kj
    std::vector<double> center, scale;        ///< the fit is done in (x - center)/scale
    std::vector<double> scaled_coefficients;  ///< coefficients in the scaled variables
    std::vector<double> minimum, maximum;     ///< range of each variable in the data (validity window)
    std::size_t points = 0;
    double r_squared = 0;
    double max_abs_residual = 0;
    double rms_residual = 0;
    std::string note; ///< e.g. how a derived response was obtained

    /// Evaluates the fit (in scaled variables, the well-conditioned form).
    double operator()(const std::vector<double> &x) const;
    Json to_json() const;
  };

  /// Exponent lists of the full polynomial with the given largest power of each variable
  /// (all x1^a x2^b ... with a <= degrees[0], b <= degrees[1], ...).
  std::vector<std::vector<unsigned int>> full_polynomial_exponents(const std::vector<int> &degrees);

  /// Fits y ~ sum_k c_k prod_j x_j^e_kj. points[i] holds the variables of sample i. The exponent set
  /// must contain every lower power of its terms (true for full polynomials and the paper's forms),
  /// so that the physical coefficients follow from the scaled ones. Throws std::invalid_argument if
  /// there are fewer samples than terms.
  PolynomialFit fit_polynomial(const std::vector<std::vector<double>> &points, const std::vector<double> &values,
                               const std::vector<std::vector<unsigned int>> &exponents);
} // namespace servodrift
