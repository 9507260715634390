#include "flow/fv/newton_ptc.h"

#include <Eigen/UmfPackSupport>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace servodrift::flow
{
  namespace
  {
    double seconds_since(std::chrono::steady_clock::time_point t0)
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    /// a CFL this far below the start's means the pseudo-time path is stuck
    constexpr double smallest_cfl_ratio = 1e-8;
    /// step halvings before the CFL is cut
    constexpr unsigned int max_halvings = 3;
    /// accepted steps over which the norm must at least halve
    constexpr std::size_t stall_window = 10;

    bool same_pattern(const Eigen::SparseMatrix<double> &a, const Eigen::SparseMatrix<double> &b)
    {
      return a.rows() == b.rows() && a.nonZeros() == b.nonZeros() &&
             std::equal(a.outerIndexPtr(), a.outerIndexPtr() + a.outerSize() + 1, b.outerIndexPtr()) &&
             std::equal(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros(), b.innerIndexPtr());
    }
  } // namespace

  std::string to_string(PtcOutcome outcome)
  {
    switch (outcome)
      {
      case PtcOutcome::converged: return "converged";
      case PtcOutcome::stalled: return "stalled";
      case PtcOutcome::non_finite: return "non-finite start";
      }
    return "?";
  }

  PtcReport solve_ptc(PtcProblem &problem, Eigen::VectorXd &x, const PtcSettings &settings)
  {
    using Clock = std::chrono::steady_clock;
    PtcReport report;
    report.unknowns = x.size();
    const Eigen::Index n = x.size();
    Eigen::VectorXd R(n), R_trial(n), P(n), x_trial(n);
    auto evaluate = [&](const Eigen::VectorXd &at, Eigen::VectorXd &r) {
      const auto t0 = Clock::now();
      const bool ok = problem.residual(at, r) && r.allFinite();
      report.residual_seconds += seconds_since(t0);
      ++report.residual_evaluations;
      return ok;
    };
    if (!evaluate(x, R))
      {
        report.outcome = PtcOutcome::non_finite;
        return report;
      }
    double norm = problem.norm(R);
    const double norm0 = std::max(norm, 1e-300);
    report.history.push_back(norm);
    // SER, times the cuts of failed steps: CFL = cut CFL_0 ||R_0|| / ||R||
    double cut = 1;
    auto ser_cfl = [&] {
      return std::min(settings.largest_cfl, cut * settings.initial_cfl * norm0 / std::max(norm, 1e-300));
    };
    Eigen::SparseMatrix<double> J, M;
    Eigen::UmfPackLU<Eigen::SparseMatrix<double>> lu;
    Eigen::SparseMatrix<double> analysed_pattern;
    bool factorised = false;
    double last_contraction = 1; ///< the norm's ratio over the last accepted step
    // a stall: the norm not halved over the last stall_window accepted steps (a limiter or a floor
    // switching between states keeps it hovering; more steps would not help)
    auto stalled = [&] {
      const auto &h = report.history;
      return h.size() > stall_window && h.back() > 0.5 * h[h.size() - 1 - stall_window];
    };
    while (norm > settings.tolerance && report.steps < settings.max_steps && !stalled())
      {
        // chord steps: the last factorisation again while steps contract well (a Jacobian and an LU
        // cost tens to hundreds of residuals)
        if (factorised && last_contraction < settings.chord_contraction)
          {
            auto t0 = Clock::now();
            const Eigen::VectorXd dx = lu.solve(Eigen::VectorXd(-R));
            report.factorisation_seconds += seconds_since(t0);
            x_trial = x + dx;
            if (dx.allFinite() && evaluate(x_trial, R_trial))
              {
                const double trial_norm = problem.norm(R_trial);
                if (trial_norm < settings.chord_contraction * norm || trial_norm < settings.tolerance)
                  {
                    x.swap(x_trial), R.swap(R_trial);
                    last_contraction = trial_norm / norm;
                    norm = trial_norm;
                    ++report.steps, ++report.chord_steps;
                    report.history.push_back(norm);
                    continue;
                  }
              }
          }
        auto t0 = Clock::now();
        problem.jacobian(x, R, J);
        problem.pseudo_time_mass(x, P);
        report.jacobian_seconds += seconds_since(t0);
        ++report.jacobians;
        report.jacobian_entries = J.nonZeros();
        bool accepted = false;
        for (; !accepted && cut >= smallest_cfl_ratio;)
          {
            const double cfl = ser_cfl();
            t0 = Clock::now();
            M = J;
            for (Eigen::Index i = 0; i < n; ++i)
              if (P[i] > 0)
                M.coeffRef(i, i) += P[i] / cfl;
            // the symbolic analysis anew only when the pattern changed (a finite-difference
            // Jacobian drops entries that happen to be zero)
            if (!same_pattern(M, analysed_pattern))
              lu.analyzePattern(M), analysed_pattern = M;
            lu.factorize(M);
            factorised = lu.info() == Eigen::Success;
            Eigen::VectorXd dx;
            if (lu.info() == Eigen::Success)
              dx = lu.solve(Eigen::VectorXd(-R));
            report.factorisation_seconds += seconds_since(t0);
            if (lu.info() != Eigen::Success || !dx.allFinite())
              {
                cut *= 0.1;
                continue;
              }
            double lambda = 1;
            for (unsigned int h = 0; h <= max_halvings && !accepted; ++h, lambda *= 0.5)
              {
                x_trial = x + lambda * dx;
                if (!evaluate(x_trial, R_trial))
                  continue;
                const double trial_norm = problem.norm(R_trial);
                if (trial_norm <= settings.growth_allowed * norm || trial_norm < settings.tolerance)
                  {
                    x.swap(x_trial), R.swap(R_trial);
                    last_contraction = trial_norm / norm;
                    norm = trial_norm;
                    accepted = true;
                  }
              }
            if (!accepted)
              cut *= 0.1;
          }
        if (!accepted)
          break;
        ++report.steps;
        report.history.push_back(norm);
      }
    report.norm = norm;
    report.outcome = norm <= settings.tolerance ? PtcOutcome::converged : PtcOutcome::stalled;
    return report;
  }
} // namespace servodrift::flow
