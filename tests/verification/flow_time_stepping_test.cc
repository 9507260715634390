// Verification of the flow solver's time stepping (flow/time_stepping.cc, implicit Euler; issue 28,
// item 6: the time average of a case without a steady solution).
//
// Start-up of creeping pipe flow under a pressure difference applied at t = 0 (Szymanski 1932): the
// flow rate over its steady value is Q(t)/Q_inf = 1 - 32 sum_n exp(-lambda_n^2 nu t/R^2)/lambda_n^4,
// lambda_n the zeros of J0. The pipe of the rectangle template (L = 4 R, 32 x 20 cells, Re 2e-3)
// between a total-pressure inlet and a static-pressure outlet; Q_inf is the steady solver's on the
// same mesh, so that the comparison measures the time stepping and not the mesh's steady error
// (flow_core_test.cc measures that). Implicit Euler is first order in time: at dt = 0.005 R^2/nu the
// error of its first mode at t = 0.1 R^2/nu is 0.4 % of Q_inf (lambda_1^2 dt t/2 of its amplitude),
// so the tolerance is 1 % at the times checked, and halving dt must halve the error (observed order
// between 0.8 and 1.2).
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

    /// The largest |Q/Q_inf - Szymanski| over the check times, marching from rest with dt.
    double largest_error(const FvMesh &mesh, double Q_inf, double dt)
    {
      SimplecSolver solver(mesh, {rho, mu}, pipe, settings());
      double t = 0, largest = 0;
      for (double check : check_times)
        {
          while (t < check - 1e-9)
            {
              const SolveReport step = solver.advance(dt, 500, 1e-9);
              EXPECT_LT(step.iterations, 500u) << "the step at t = " << t << " did not converge";
              t += dt;
            }
          const double Q = solver.flow_rate("right") / Q_inf, exact = start_up_flow_rate(t);
          std::printf("  dt %.4f, t %.3f: Q/Q_inf %.5f, Szymanski %.5f (%+.2e)\n", dt, t, Q, exact, Q - exact);
          largest = std::max(largest, std::abs(Q - exact));
        }
      return largest;
    }
  } // namespace

  TEST(FlowTimeStepping, StartUpPipeFlowFollowsSzymanski)
  {
    const FvMesh mesh = rectangle(Geometry::axisymmetric, 0, L, 0, R, 32, 20);
    SimplecSolver steady(mesh, {rho, mu}, pipe, settings());
    steady.solve();
    const double Q_inf = steady.flow_rate("right");
    const double coarse = largest_error(mesh, Q_inf, 0.005), fine = largest_error(mesh, Q_inf, 0.0025);
    const double order = std::log2(coarse / fine);
    std::printf("start-up pipe flow: largest error %.2e (dt 0.005), %.2e (dt 0.0025), observed order %.2f\n", coarse,
                fine, order);
    EXPECT_LT(coarse, 1e-2);
    EXPECT_GT(order, 0.8);
    EXPECT_LT(order, 1.2);
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
