// Anderson acceleration (flow/fv/anderson_acceleration.h) on fixed-point maps whose answers are known:
// a slow linear contraction (where it is GMRES in disguise and must beat the plain iteration by far)
// and a nonlinear one; the fixed point must be the plain iteration's.
#include "flow/fv/anderson_acceleration.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>

using servodrift::flow::AndersonAcceleration;

namespace
{
  /// G(x) = M x + b with M symmetric, eigenvalues spread over [0, 0.99]: the plain iteration
  /// converges as 0.99^n (about 1 800 iterations for 1e-8).
  struct LinearContraction
  {
    Eigen::MatrixXd M;
    Eigen::VectorXd b;
    explicit LinearContraction(int n)
    {
      Eigen::MatrixXd Q = Eigen::HouseholderQR<Eigen::MatrixXd>(Eigen::MatrixXd::Random(n, n)).householderQ();
      Eigen::VectorXd lambda(n);
      for (int i = 0; i < n; ++i)
        lambda[i] = 0.99 * i / (n - 1);
      M = Q * lambda.asDiagonal() * Q.transpose();
      b = Eigen::VectorXd::LinSpaced(n, -1, 1);
    }
    Eigen::VectorXd operator()(const Eigen::VectorXd &x) const { return M * x + b; }
    Eigen::VectorXd fixed_point() const
    {
      return (Eigen::MatrixXd::Identity(M.rows(), M.cols()) - M).partialPivLu().solve(b);
    }
  };

  /// Iterations until |G(x) - x| < tolerance |G(0)|, with or without acceleration.
  template <typename Map>
  int iterations_to_converge(const Map &G, int n, unsigned int depth, Eigen::VectorXd &x, double tolerance = 1e-10)
  {
    x = Eigen::VectorXd::Zero(n);
    const double reference = G(x).norm();
    AndersonAcceleration anderson(depth > 0 ? depth : 1);
    for (int it = 1; it <= 100000; ++it)
      {
        const Eigen::VectorXd g = G(x);
        if ((g - x).norm() < tolerance * reference)
          return it;
        x = depth > 0 ? anderson.next(x, g) : g;
      }
    return -1;
  }
} // namespace

TEST(AndersonAcceleration, SlowLinearContractionConvergesFarFasterToTheSameFixedPoint)
{
  const int n = 60;
  const LinearContraction G(n);
  const Eigen::VectorXd exact = G.fixed_point();
  Eigen::VectorXd plain, accelerated;
  const int plain_iterations = iterations_to_converge(G, n, 0, plain);
  const int accelerated_iterations = iterations_to_converge(G, n, 10, accelerated);
  std::printf("linear contraction, rate 0.99: plain %d iterations, Anderson(10) %d\n", plain_iterations,
              accelerated_iterations);
  ASSERT_GT(plain_iterations, 0);
  ASSERT_GT(accelerated_iterations, 0);
  // the plain rate 0.99 needs up to ln(1e-10)/ln(0.99) ~ 2 300 iterations (fewer as b is not all
  // along the slowest direction); a Krylov method of depth 10 on the spectrum of I - M in [0.01, 1]
  // needs a few hundred at most: ask for five times fewer
  EXPECT_GT(plain_iterations, 1500);
  EXPECT_LT(5 * accelerated_iterations, plain_iterations);
  // both are converged to 1e-10 of |b| in the change; the error is at most that over 1 - 0.99
  EXPECT_LT((accelerated - exact).norm(), 1e-7 * exact.norm());
  EXPECT_LT((plain - exact).norm(), 1e-7 * exact.norm());
}

TEST(AndersonAcceleration, NonlinearContractionKeepsItsFixedPoint)
{
  // G(x)_i = 0.95 cos(x_(i+1)) / 2 + 0.95 x_i / 2 + 0.1 i/n: a mildly nonlinear contraction
  const int n = 40;
  auto G = [n](const Eigen::VectorXd &x) {
    Eigen::VectorXd g(n);
    for (int i = 0; i < n; ++i)
      g[i] = 0.475 * std::cos(x[(i + 1) % n]) + 0.475 * x[i] + 0.1 * i / n;
    return g;
  };
  Eigen::VectorXd plain, accelerated;
  const int plain_iterations = iterations_to_converge(G, n, 0, plain, 1e-12);
  const int accelerated_iterations = iterations_to_converge(G, n, 5, accelerated, 1e-12);
  std::printf("nonlinear contraction: plain %d iterations, Anderson(5) %d\n", plain_iterations, accelerated_iterations);
  ASSERT_GT(plain_iterations, 0);
  ASSERT_GT(accelerated_iterations, 0);
  EXPECT_LT(accelerated_iterations, plain_iterations);
  EXPECT_LT((accelerated - plain).norm(), 1e-9 * plain.norm());
}

TEST(AndersonAcceleration, RefusesZeroDepthAndRestartsCleanly)
{
  EXPECT_THROW(AndersonAcceleration(0), std::invalid_argument);
  AndersonAcceleration anderson(3);
  const Eigen::VectorXd x = Eigen::VectorXd::Zero(4), g = Eigen::VectorXd::Ones(4);
  EXPECT_TRUE(anderson.next(x, g).isApprox(g)); // no history: the plain step
  anderson.next(g, 2 * g);
  EXPECT_EQ(anderson.history_size(), 1u);
  anderson.restart();
  EXPECT_EQ(anderson.history_size(), 0u);
  EXPECT_TRUE(anderson.next(x, g).isApprox(g));
}
