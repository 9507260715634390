// Newton-PTC (flow/fv/newton_ptc.h) on small problems whose answers and behaviour are known, in
// milliseconds: a nonlinear system with an exact Jacobian (quadratic convergence once the pseudo step
// has grown), one with no root (a stall, reported as a value), a start outside the problem's domain,
// and a problem whose full Newton step leaves the domain (the step is halved, never taken).
#include "flow/fv/newton_ptc.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace servodrift::flow;

namespace
{
  /// R_i(x) = x_i^3 + x_i - c_i, with the exact Jacobian diag(3 x_i^2 + 1): one root per i; x_i below
  /// `lower' is outside the problem's domain (residual() refuses it).
  struct Cubic : PtcProblem
  {
    Eigen::VectorXd c;
    double lower = -1e300;
    bool residual(const Eigen::VectorXd &x, Eigen::VectorXd &R) override
    {
      if ((x.array() < lower).any())
        return false;
      R = x.array().cube() + x.array() - c.array();
      return true;
    }
    void jacobian(const Eigen::VectorXd &x, const Eigen::VectorXd &, Eigen::SparseMatrix<double> &J) override
    {
      J.resize(x.size(), x.size());
      std::vector<Eigen::Triplet<double>> t;
      for (Eigen::Index i = 0; i < x.size(); ++i)
        t.emplace_back(i, i, 3 * x[i] * x[i] + 1);
      J.setFromTriplets(t.begin(), t.end());
    }
    void pseudo_time_mass(const Eigen::VectorXd &x, Eigen::VectorXd &P) override { P.setOnes(x.size()); }
    double norm(const Eigen::VectorXd &R) const override { return R.lpNorm<Eigen::Infinity>(); }
  };

  /// R(x) = atan(x): Newton's step from |x| > 1.39 overshoots the root at 0 to the other side, further
  /// out; refused below `lower'.
  struct Arctan : Cubic
  {
    bool residual(const Eigen::VectorXd &x, Eigen::VectorXd &R) override
    {
      if ((x.array() < lower).any())
        return false;
      R = x.array().atan();
      return true;
    }
    void jacobian(const Eigen::VectorXd &x, const Eigen::VectorXd &, Eigen::SparseMatrix<double> &J) override
    {
      J.resize(x.size(), x.size());
      std::vector<Eigen::Triplet<double>> t;
      for (Eigen::Index i = 0; i < x.size(); ++i)
        t.emplace_back(i, i, 1 / (1 + x[i] * x[i]));
      J.setFromTriplets(t.begin(), t.end());
    }
  };

  /// R(x) = x^2 + 1: no real root; the norm cannot fall below 1.
  struct NoRoot : Cubic
  {
    bool residual(const Eigen::VectorXd &x, Eigen::VectorXd &R) override
    {
      R = x.array().square() + 1;
      return true;
    }
    void jacobian(const Eigen::VectorXd &x, const Eigen::VectorXd &, Eigen::SparseMatrix<double> &J) override
    {
      J.resize(x.size(), x.size());
      std::vector<Eigen::Triplet<double>> t;
      for (Eigen::Index i = 0; i < x.size(); ++i)
        t.emplace_back(i, i, 2 * x[i]);
      J.setFromTriplets(t.begin(), t.end());
    }
  };
} // namespace

TEST(NewtonPtc, ConvergesQuadraticallyOnceThePseudoStepHasGrown)
{
  Cubic problem;
  problem.c = Eigen::VectorXd::LinSpaced(20, -30, 30);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(20);
  PtcSettings settings;
  settings.initial_cfl = 10;
  const PtcReport r = solve_ptc(problem, x, settings);
  ASSERT_EQ(r.outcome, PtcOutcome::converged);
  EXPECT_LT(r.norm, 1e-10);
  // the root of x^3 + x = c, each
  for (Eigen::Index i = 0; i < x.size(); ++i)
    EXPECT_NEAR(x[i] * x[i] * x[i] + x[i], problem.c[i], 1e-10);
  // the last steps: the error squared (a ratio of successive norms that falls with the norm)
  const auto &h = r.history;
  ASSERT_GE(h.size(), 4u);
  const std::size_t k = h.size() - 1;
  EXPECT_LT(h[k] / h[k - 1], h[k - 1] / h[k - 2]);
  EXPECT_LT(r.steps, 30u);
}

TEST(NewtonPtc, AProblemWithoutRootStallsAsAValue)
{
  NoRoot problem;
  Eigen::VectorXd x = Eigen::VectorXd::Constant(3, 2.0);
  const PtcReport r = solve_ptc(problem, x, {});
  EXPECT_EQ(r.outcome, PtcOutcome::stalled);
  EXPECT_GE(r.norm, 1.0);
  EXPECT_TRUE(x.allFinite());
}

TEST(NewtonPtc, AStartOutsideTheDomainIsReportedNotSolved)
{
  Cubic problem;
  problem.c = Eigen::VectorXd::Ones(2);
  problem.lower = 0;
  Eigen::VectorXd x = Eigen::VectorXd::Constant(2, -1.0);
  const PtcReport r = solve_ptc(problem, x, {});
  EXPECT_EQ(r.outcome, PtcOutcome::non_finite);
  EXPECT_EQ(r.steps, 0u);
  EXPECT_EQ(x, Eigen::VectorXd::Constant(2, -1.0));
}

TEST(NewtonPtc, AStepOutOfTheDomainIsShortenedNeverTaken)
{
  // atan from x = 3: Newton's full step lands at -9.5, where the problem refuses (below -1); the step
  // is halved until it stands, every accepted state stays in the domain, and the root is still found
  Arctan problem;
  problem.lower = -1;
  Eigen::VectorXd x = Eigen::VectorXd::Constant(1, 3.0);
  PtcSettings settings;
  settings.initial_cfl = 1e12; // Newton's step at once
  const PtcReport r = solve_ptc(problem, x, settings);
  EXPECT_EQ(r.outcome, PtcOutcome::converged);
  EXPECT_NEAR(x[0], 0.0, 1e-10);
  EXPECT_GT(r.residual_evaluations, r.steps + 1); // refused trials were evaluated, not taken
}
