#include "common/fitting.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace servodrift
{
  namespace
  {
    double term(const std::vector<unsigned int> &e, const double *x)
    {
      double v = 1;
      for (std::size_t j = 0; j < e.size(); ++j)
        for (unsigned int p = 0; p < e[j]; ++p)
          v *= x[j];
      return v;
    }

    double binomial(unsigned int n, unsigned int k)
    {
      double b = 1;
      for (unsigned int i = 1; i <= k; ++i)
        b = b * (n - k + i) / i;
      return b;
    }
  } // namespace

  std::vector<std::vector<unsigned int>> full_polynomial_exponents(const std::vector<int> &degrees)
  {
    std::vector<std::vector<unsigned int>> out{{}};
    for (int d : degrees)
      {
        std::vector<std::vector<unsigned int>> next;
        for (const auto &e : out)
          for (int p = 0; p <= d; ++p)
            {
              auto f = e;
              f.push_back(static_cast<unsigned int>(p));
              next.push_back(f);
            }
        out = next;
      }
    return out;
  }

  PolynomialFit fit_polynomial(const std::vector<std::vector<double>> &points, const std::vector<double> &values,
                               const std::vector<std::vector<unsigned int>> &exponents)
  {
    const std::size_t n = points.size(), n_terms = exponents.size();
    if (n == 0 || values.size() != n)
      throw std::invalid_argument("fit_polynomial: no samples, or samples and values differ in number");
    if (n < n_terms)
      throw std::invalid_argument("fit_polynomial: " + std::to_string(n) + " samples for " + std::to_string(n_terms) +
                                  " terms");
    const std::size_t d = points[0].size();
    PolynomialFit fit;
    fit.exponents = exponents;
    fit.points = n;
    fit.minimum.assign(d, 0);
    fit.maximum.assign(d, 0);
    fit.center.assign(d, 0);
    fit.scale.assign(d, 1);
    for (std::size_t j = 0; j < d; ++j)
      {
        double lo = points[0][j], hi = points[0][j];
        for (const auto &p : points)
          lo = std::min(lo, p[j]), hi = std::max(hi, p[j]);
        fit.minimum[j] = lo;
        fit.maximum[j] = hi;
        fit.center[j] = 0.5 * (lo + hi);
        fit.scale[j] = hi > lo ? 0.5 * (hi - lo) : 1.0;
      }

    // Least squares in the scaled variables s = (x - center)/scale: well conditioned for any units.
    Eigen::MatrixXd A(n, n_terms);
    Eigen::VectorXd b(n);
    std::vector<double> s(d);
    for (std::size_t i = 0; i < n; ++i)
      {
        for (std::size_t j = 0; j < d; ++j)
          s[j] = (points[i][j] - fit.center[j]) / fit.scale[j];
        for (std::size_t k = 0; k < n_terms; ++k)
          A(i, k) = term(exponents[k], s.data());
        b(i) = values[i];
      }
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
    if (qr.rank() < static_cast<Eigen::Index>(n_terms))
      throw std::invalid_argument("fit_polynomial: the samples do not determine all " + std::to_string(n_terms) +
                                  " terms (rank " + std::to_string(qr.rank()) + ")");
    const Eigen::VectorXd c = qr.solve(b);
    fit.scaled_coefficients.assign(c.data(), c.data() + n_terms);

    const Eigen::VectorXd residual = A * c - b;
    const double mean = b.mean();
    const double ss_res = residual.squaredNorm(), ss_tot = (b.array() - mean).square().sum();
    fit.r_squared = ss_tot > 0 ? 1.0 - ss_res / ss_tot : (ss_res == 0 ? 1.0 : 0.0);
    fit.max_abs_residual = residual.cwiseAbs().maxCoeff();
    fit.rms_residual = std::sqrt(ss_res / n);

    // Physical coefficients: expand prod_j ((x_j - c_j)/s_j)^e_j into powers of x_j.
    std::map<std::vector<unsigned int>, double> physical;
    for (const auto &e : exponents)
      physical[e] = 0;
    for (std::size_t k = 0; k < n_terms; ++k)
      {
        std::vector<std::pair<std::vector<unsigned int>, double>> expansion{{std::vector<unsigned int>(d, 0), c(k)}};
        for (std::size_t j = 0; j < d; ++j)
          {
            std::vector<std::pair<std::vector<unsigned int>, double>> next;
            const unsigned int e = exponents[k][j];
            for (const auto &[powers, coefficient] : expansion)
              for (unsigned int q = 0; q <= e; ++q)
                {
                  auto p = powers;
                  p[j] = q;
                  next.emplace_back(p, coefficient * binomial(e, q) * std::pow(-fit.center[j], e - q) /
                                         std::pow(fit.scale[j], e));
                }
            expansion = next;
          }
        for (const auto &[powers, coefficient] : expansion)
          {
            const auto it = physical.find(powers);
            if (it == physical.end())
              throw std::invalid_argument("fit_polynomial: the exponent set lacks a lower power of one of its terms");
            it->second += coefficient;
          }
      }
    for (const auto &e : exponents)
      fit.coefficients.push_back(physical[e]);
    return fit;
  }

  double PolynomialFit::operator()(const std::vector<double> &x) const
  {
    std::vector<double> s(x.size());
    for (std::size_t j = 0; j < x.size(); ++j)
      s[j] = (x[j] - center[j]) / scale[j];
    double y = 0;
    for (std::size_t k = 0; k < exponents.size(); ++k)
      y += scaled_coefficients[k] * term(exponents[k], s.data());
    return y;
  }

  Json PolynomialFit::to_json() const
  {
    Json terms = Json::array();
    for (std::size_t k = 0; k < exponents.size(); ++k)
      {
        std::vector<double> powers(exponents[k].begin(), exponents[k].end());
        terms.push_back(Json::object().set("powers", Json(powers)).set("coefficient", coefficients[k]));
      }
    Json j = Json::object();
    j.set("name", name).set("source", source).set("response", response).set("variables", Json(variables));
    j.set("terms", terms);
    j.set("scaled_form", Json::object()
                           .set("center", Json(center))
                           .set("scale", Json(scale))
                           .set("coefficients", Json(scaled_coefficients)));
    j.set("validity", Json::object().set("minimum", Json(minimum)).set("maximum", Json(maximum)));
    j.set("points", points).set("r_squared", r_squared).set("max_abs_residual", max_abs_residual);
    j.set("rms_residual", rms_residual);
    if (!note.empty())
      j.set("note", note);
    return j;
  }
} // namespace servodrift
