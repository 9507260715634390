// Verification of the flow solver's time stepping (flow/time_stepping.cc, BDF2; issue 28,
// item 6: the time average of a case without a steady solution).
//
// Start-up of creeping pipe flow under a pressure difference applied at t = 0 (Szymanski 1932): the
// flow rate over its steady value is Q(t)/Q_inf = 1 - 32 sum_n exp(-lambda_n^2 nu t/R^2)/lambda_n^4,
// lambda_n the zeros of J0. The pipe of the rectangle template (L = 4 R, 32 x 20 cells, Re 2e-3)
// between a total-pressure inlet and a static-pressure outlet; Q_inf is the steady solver's on the
// same mesh, so that the comparison measures the time stepping and not the mesh's steady error
// (flow_core_test.cc measures that). At dt = 0.01 R^2/nu the error must stay below 0.2 % of Q_inf
// at t = 0.05 ... 0.4 R^2/nu: the abrupt start's higher modes (lambda_n^2 dt of order 1 and more)
// dominate it early; the first mode's own error, of order lambda_1^3 dt^2 t, is below 1e-4. BDF2 (its
// first step implicit Euler) is second order in time: the observed order of the differences between
// dt = 0.01, 0.005 and 0.0025 at t = 0.2 R^2/nu on the same mesh (free of the mesh's error) must lie
// between 1.7 and 2.3.
#include "flow/simplec.h"
#include "tests/verification/flow_test_domains.h"

#include <boost/math/special_functions/bessel.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace servodrift::flow
{
  using namespace domains;

  namespace
  {
    /// Szymanski's Q(t)/Q_inf at t in units of R^2/nu.
    double start_up_flow_rate(double t)
    {
      double deficit = 0;
      for (int n = 1; n <= 200; ++n)
        {
          const double lambda = boost::math::cyl_bessel_j_zero(0.0, n);
          deficit += 32 * std::exp(-lambda * lambda * t) / std::pow(lambda, 4);
        }
      return 1 - deficit;
    }

    const double L = 4, R = 1, rho = 1, mu = 1, p0 = 0.032; // U = p0 R^2/(8 mu L) = 1e-3, Re 2e-3
    const std::map<std::string, BoundaryCondition> pipe{{"left", BoundaryCondition::total_pressure_inlet(p0)},
                                                        {"right", BoundaryCondition::pressure_outlet(0)},
                                                        {"top", BoundaryCondition::wall()},
                                                        {"bottom", BoundaryCondition::axis()}};
    const std::vector<double> check_times{0.05, 0.1, 0.2, 0.4}; // [R^2/nu]

    /// Q/Q_inf at the check times, marching from rest with dt.
    std::vector<double> flow_rates(const FvMesh &mesh, double Q_inf, double dt)
    {
      SimplecSolver solver(mesh, {rho, mu}, pipe, settings());
      double t = 0;
      std::vector<double> Q;
      for (double check : check_times)
        {
          while (t < check - 1e-9)
            {
              const SolveReport step = solver.advance(dt, 500, 1e-9);
              EXPECT_LT(step.iterations, 500u) << "the step at t = " << t << " did not converge";
              t += dt;
            }
          Q.push_back(solver.flow_rate("right") / Q_inf);
          std::printf("  dt %.4f, t %.3f: Q/Q_inf %.6f, Szymanski %.6f (%+.2e)\n", dt, t, Q.back(),
                      start_up_flow_rate(t), Q.back() - start_up_flow_rate(t));
        }
      return Q;
    }
  } // namespace

  TEST(FlowTimeStepping, StartUpPipeFlowFollowsSzymanski)
  {
    const FvMesh mesh = rectangle(Geometry::axisymmetric, 0, L, 0, R, 32, 20);
    SimplecSolver steady(mesh, {rho, mu}, pipe, settings());
    steady.solve();
    const double Q_inf = steady.flow_rate("right");
    const std::vector<double> coarse = flow_rates(mesh, Q_inf, 0.01), medium = flow_rates(mesh, Q_inf, 0.005),
                              fine = flow_rates(mesh, Q_inf, 0.0025);
    double largest = 0;
    for (std::size_t i = 0; i < check_times.size(); ++i)
      largest = std::max(largest, std::abs(coarse[i] - start_up_flow_rate(check_times[i])));
    const std::size_t at = 2; // t = 0.2 R^2/nu
    const double order = std::log2(std::abs(coarse[at] - medium[at]) / std::abs(medium[at] - fine[at]));
    std::printf("start-up pipe flow: largest error at dt 0.01 %.2e; observed order in time at t = 0.2: %.2f\n", largest,
                order);
    EXPECT_LT(largest, 2e-3);
    EXPECT_GT(order, 1.7);
    EXPECT_LT(order, 2.3);
  }

  // Marched long enough, the transient lands on the steady solver's fields: the time stepping adds
  // nothing to the steady equations at a fixed point (to the inner tolerance, 1e-9, and the
  // remaining decay exp(-lambda_1^2 t) at t = 4 R^2/nu, 1e-10).
  TEST(FlowTimeStepping, LandsOnTheSteadySolution)
  {
    const FvMesh mesh = rectangle(Geometry::axisymmetric, 0, L, 0, R, 16, 10);
    SimplecSolver steady(mesh, {rho, mu}, pipe, settings());
    steady.solve();
    SimplecSolver marched(mesh, {rho, mu}, pipe, settings());
    for (int step = 0; step < 40; ++step)
      marched.advance(0.1, 500, 1e-9);
    const double Q = marched.flow_rate("right") / steady.flow_rate("right") - 1;
    std::printf("marched to t = 4 R^2/nu: Q/Q_steady - 1 = %.2e\n", Q);
    EXPECT_LT(std::abs(Q), 1e-6);
  }

  TEST(FlowTimeStepping, RefusesTurbulenceAndBadSteps)
  {
    const FvMesh mesh = rectangle(Geometry::axisymmetric, 0, L, 0, R, 8, 4);
    SimplecSolver laminar(mesh, {rho, mu}, pipe, settings());
    EXPECT_THROW(laminar.advance(0, 10, 1e-6), std::invalid_argument);
    EXPECT_THROW(laminar.advance(-1, 10, 1e-6), std::invalid_argument);
    EXPECT_THROW(laminar.courant_time_step(1), std::invalid_argument); // at rest: no flow to set it by
    auto s = settings();
    s.turbulence = FlowSolverParameters::Turbulence::k_epsilon;
    SimplecSolver turbulent(mesh, {rho, mu}, pipe, s);
    EXPECT_THROW(turbulent.advance(0.1, 10, 1e-6), std::invalid_argument);
  }

  // The Courant time step: after the steady solve, dt for Courant number 1 against the largest
  // cell's sum|F|/(2 rho V), here a cell on the axis of the developed flow: 2 U/dx (in and out).
  TEST(FlowTimeStepping, CourantTimeStepOfTheDevelopedPipe)
  {
    const FvMesh mesh = rectangle(Geometry::axisymmetric, 0, L, 0, R, 16, 10);
    SimplecSolver steady(mesh, {rho, mu}, pipe, settings());
    steady.solve();
    const double U = p0 * R * R / (8 * mu * L), u_axis = 2 * U, dx = L / 16;
    const double dt = steady.courant_time_step(1);
    std::printf("Courant time step %.4e s, developed axis estimate dx/u_axis %.4e s\n", dt, dx / u_axis);
    EXPECT_NEAR(dt / (dx / u_axis), 1, 0.1); // the axis cell's u is the parabola's mean over the cell
  }
} // namespace servodrift::flow
