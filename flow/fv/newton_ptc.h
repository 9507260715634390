#pragma once
// Newton's method globalised by pseudo-transient continuation (PTC; Kelley and Keyes, SIAM J.
// Numer. Anal. 35 (1998) 508) for a steady discrete problem R(x) = 0:
//   (P / dtau_k + J(x_k)) dx = -R(x_k),   x_(k+1) = x_k + lambda dx,
// P a non-negative diagonal (the pseudo time's mass: zero on algebraic rows such as continuity),
// J = dR/dx, and the pseudo step by switched evolution relaxation (SER, Mulder and van Leer 1985):
// CFL_k = CFL_0 ||R_0|| / ||R_k||, so that the step grows to Newton's as the residual falls. A step
// whose norm grows by more than `growth_allowed' is halved (lambda) and, if halving does not help,
// retried with a ten times smaller CFL. While steps contract well, the next reuses the last
// factorisation (a chord step) before a new Jacobian is made. The linear system is factorised by
// UMFPACK (sparse LU), its symbolic analysis kept while the pattern stays the same. Outcomes are
// values (PtcOutcome).
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <string>
#include <vector>

namespace servodrift::flow
{
  /// What a PTC solve needs of its problem.
  class PtcProblem
  {
  public:
    virtual ~PtcProblem() = default;
    /// R(x); returns false if x is outside the problem's domain (a non-finite
    /// value).
    virtual bool residual(const Eigen::VectorXd &x, Eigen::VectorXd &R) = 0;
    /// J = dR/dx at x, whose residual is R (on the same pattern at every call).
    virtual void jacobian(const Eigen::VectorXd &x, const Eigen::VectorXd &R, Eigen::SparseMatrix<double> &J) = 0;
    /// P per unknown at x: the pseudo time's mass (0 for algebraic rows).
    virtual void pseudo_time_mass(const Eigen::VectorXd &x, Eigen::VectorXd &P) = 0;
    /// The scaled norm of a residual that convergence is judged on [1].
    virtual double norm(const Eigen::VectorXd &R) const = 0;
  };

  struct PtcSettings
  {
    double initial_cfl = 1;    ///< CFL_0 [1]
    double largest_cfl = 1e12; ///< SER's cap [1]
    double tolerance = 1e-10;  ///< on the scaled norm [1]
    unsigned int max_steps = 200;
    double growth_allowed = 1.0; ///< a step may raise the norm by this factor and still stand [1]
    /// chord steps (the last LU again) while each step cuts the norm at least by this factor [1]
    double chord_contraction = 0.25;
  };

  enum class PtcOutcome
  {
    converged,
    stalled,   ///< the step budget ran out, the norm did not halve over 10 steps, or the CFL fell below 1e-8 of CFL_0
    non_finite ///< the start's residual is not finite
  };

  struct PtcReport
  {
    PtcOutcome outcome = PtcOutcome::stalled;
    unsigned int steps = 0, residual_evaluations = 0, jacobians = 0;
    unsigned int chord_steps = 0; ///< steps with an earlier Jacobian's LU
    bool limiter_held = false;    ///< the problem held a non-differentiable part near the solution
    unsigned int colours = 0;
    std::size_t jacobian_entries = 0; ///< non-zeros of the last Jacobian
    std::size_t unknowns = 0;         ///< residual evaluations per Jacobian (a coloured
                                      ///< finite-difference one)
    double norm = 0;                  ///< of the final state
    std::vector<double> history;      ///< the norm after each accepted step (the start first)
    double jacobian_seconds = 0, factorisation_seconds = 0, residual_seconds = 0;
  };

  PtcReport solve_ptc(PtcProblem &problem, Eigen::VectorXd &x, const PtcSettings &settings);
  std::string to_string(PtcOutcome outcome);
} // namespace servodrift::flow
