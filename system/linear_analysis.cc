#include "system/linear_analysis.h"

#include "common/root_finding.h"
#include "common/units.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace servodrift::system
{
  namespace
  {
    /// S^-1 A S with S = diag(scales): the same eigenvalues, but entries of comparable size.
    Eigen::MatrixXd scaled(const Eigen::MatrixXd &A, const std::vector<double> &s)
    {
      Eigen::MatrixXd M = A;
      for (Eigen::Index j = 0; j < A.rows(); ++j)
        for (Eigen::Index k = 0; k < A.cols(); ++k)
          M(j, k) *= s[k] / s[j];
      return M;
    }

    /// The row vector C of an output, on the physical states.
    Eigen::RowVectorXd output_row(const Linearisation &l, Output output)
    {
      Eigen::RowVectorXd C = Eigen::RowVectorXd::Zero(l.A.rows());
      switch (output)
        {
          case Output::brake_pressure: C(6) = 1; break;
          case Output::spool_displacement: C(4) = 1; break;
          case Output::flapper_displacement: C(0) = l.pivot_to_nozzle_distance; break;
          case Output::control_pressure_difference: C(2) = 1, C(3) = -1; break;
        }
      return C;
    }
  } // namespace

  const char *to_string(Output o)
  {
    switch (o)
      {
        case Output::brake_pressure: return "brake_pressure";
        case Output::spool_displacement: return "spool_displacement";
        case Output::flapper_displacement: return "flapper_displacement";
        case Output::control_pressure_difference: return "control_pressure_difference";
      }
    return "?";
  }

  Linearisation linearise(const ValveDynamics &dynamics, const ValveState &point, double command)
  {
    Linearisation l;
    dynamics.linearise(dynamics.vector_of(point), command, l.A, l.B);
    l.scales = dynamics.scales();
    l.pivot_to_nozzle_distance = dynamics.equations().pivot_to_nozzle_distance();
    return l;
  }

  double output_of(const Linearisation &l, Output output, const std::vector<double> &y)
  {
    const Eigen::RowVectorXd C = output_row(l, output);
    double v = 0;
    for (Eigen::Index k = 0; k < C.size(); ++k)
      v += C(k) * y[k];
    return v;
  }

  std::vector<std::complex<double>> eigenvalues(const Eigen::MatrixXd &A, const std::vector<double> &scales)
  {
    Eigen::EigenSolver<Eigen::MatrixXd> solver(scaled(A, scales), false);
    std::vector<std::complex<double>> out(solver.eigenvalues().data(), solver.eigenvalues().data() + A.rows());
    std::sort(out.begin(), out.end(), [](auto a, auto b) { return std::abs(a) < std::abs(b); });
    return out;
  }

  double slowest_decay_rate(const Linearisation &l)
  {
    double rate = std::numeric_limits<double>::infinity();
    for (const auto &lambda : eigenvalues(l.A, l.scales))
      rate = std::min(rate, -lambda.real());
    return rate;
  }

  std::vector<Mode> modes(const Linearisation &l)
  {
    Eigen::EigenSolver<Eigen::MatrixXd> solver(scaled(l.A, l.scales));
    const Eigen::MatrixXcd V = solver.eigenvectors();
    const Eigen::MatrixXcd W = V.inverse(); // rows: left eigenvectors, W V = I
    const Eigen::Index n = l.A.rows();
    std::vector<Mode> out;
    for (Eigen::Index i = 0; i < n; ++i)
      {
        const std::complex<double> lambda = solver.eigenvalues()(i);
        if (lambda.imag() < 0)
          continue; // its conjugate stands for the pair
        Mode m;
        m.eigenvalue = lambda;
        m.natural_frequency = std::abs(lambda) / (2 * units::pi);
        m.damping_ratio = std::abs(lambda) > 0 ? -lambda.real() / std::abs(lambda) : 1.0;
        m.participation.fill(0.0);
        double total = 0;
        for (Eigen::Index k = 0; k < n; ++k)
          {
            const double p = std::abs(V(k, i) * W(i, k));
            m.participation[static_cast<std::size_t>(group_of_state(k))] += p;
            total += p;
          }
        for (double &p : m.participation)
          p /= total;
        // named after every group that takes a quarter or more of it (a coupled mode has two), in
        // the fixed group order, so that a near tie does not flip the name between temperatures
        const double largest = *std::max_element(m.participation.begin(), m.participation.end());
        for (std::size_t g = 0; g < n_state_groups; ++g)
          if (m.participation[g] >= std::min(0.25, largest))
            m.name += (m.name.empty() ? "" : " + ") + std::string(to_string(static_cast<StateGroup>(g)));
        out.push_back(m);
      }
    std::sort(out.begin(), out.end(), [](const Mode &a, const Mode &b) { return a.natural_frequency < b.natural_frequency; });
    // a second mode of the same group gets a number: "pilot pressures 2"
    std::map<std::string, int> count;
    for (auto &m : out)
      if (const int k = ++count[m.name]; k > 1)
        m.name += " " + std::to_string(k);
    return out;
  }

  Eigen::VectorXcd state_response(const Linearisation &l, double f)
  {
    const Eigen::Index n = l.A.rows();
    Eigen::MatrixXcd M = -scaled(l.A, l.scales).cast<std::complex<double>>();
    M.diagonal().array() += std::complex<double>(0, 2 * units::pi * f);
    Eigen::VectorXcd b(n);
    for (Eigen::Index k = 0; k < n; ++k)
      b(k) = l.B(k) / l.scales[k];
    Eigen::VectorXcd x = M.partialPivLu().solve(b);
    for (Eigen::Index k = 0; k < n; ++k)
      x(k) *= l.scales[k];
    return x;
  }

  std::complex<double> transfer(const Linearisation &l, Output output, double f)
  {
    return (output_row(l, output).cast<std::complex<double>>() * state_response(l, f))(0);
  }

  FrequencyResponse frequency_response(const Linearisation &l, Output output, double f_min, double f_max,
                                       unsigned int points)
  {
    FrequencyResponse r;
    r.output = output;
    r.dc_gain = transfer(l, output, 0.0);
    const auto relative = [&](double f) { return transfer(l, output, f) / r.dc_gain; };
    const auto db = [&](double f) { return 20 * std::log10(std::abs(relative(f))); };
    for (unsigned int k = 0; k < points; ++k)
      {
        const double f = f_min * std::pow(f_max / f_min, double(k) / (points - 1));
        r.frequencies.push_back(f);
        r.values.push_back(transfer(l, output, f));
        const std::complex<double> h = r.values.back() / r.dc_gain;
        r.amplitude_db.push_back(20 * std::log10(std::abs(h)));
        double phase = std::arg(h) / units::degree;
        if (k > 0) // continuous: the step from the previous point is the argument of their ratio
          phase = r.phase_degrees.back() + std::arg(r.values[k] / r.values[k - 1]) / units::degree;
        r.phase_degrees.push_back(phase);
      }
    // crossings, refined on log f between the grid points that bracket them
    for (std::size_t k = 1; k < r.frequencies.size() && !r.bandwidth; ++k)
      if (r.amplitude_db[k - 1] > -3 && r.amplitude_db[k] <= -3)
        {
          const auto g = [&](double u) { return db(std::exp(u)) + 3; };
          const double a = std::log(r.frequencies[k - 1]), b = std::log(r.frequencies[k]);
          r.bandwidth = std::exp(find_root(g, a, b, g(a), g(b), 1e-12, "-3 dB frequency"));
        }
    for (std::size_t k = 1; k < r.frequencies.size() && !r.phase_90_frequency; ++k)
      if (r.phase_degrees[k - 1] > -90 && r.phase_degrees[k] <= -90)
        {
          const double f0 = r.frequencies[k - 1], phase0 = r.phase_degrees[k - 1];
          const auto g = [&](double u) {
            return phase0 + std::arg(transfer(l, output, std::exp(u)) / r.values[k - 1]) / units::degree + 90;
          };
          const double a = std::log(f0), b = std::log(r.frequencies[k]);
          r.phase_90_frequency = std::exp(find_root(g, a, b, g(a), g(b), 1e-12, "-90 degree frequency"));
        }
    return r;
  }
} // namespace servodrift::system
