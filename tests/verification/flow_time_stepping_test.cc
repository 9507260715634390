// Verification of the flow solver's time stepping (flow/fv/time_stepping.cc, BDF2; issue 28,
// item 6: the time average of a case without a steady solution), laminar and turbulent.
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
#include "flow/fv/cavitation_model.h"
#include "flow/fv/continuity.h"
#include "flow/fv/simplec.h"
#include "tests/support/checks.h"
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
  using test::larger;
  using test::smaller;

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

    /// A turbulence model as a check names it.
    const char *label(FlowSolverParameters::Turbulence t)
    {
      switch (t)
        {
          case FlowSolverParameters::Turbulence::k_epsilon: return "two-layer k-epsilon";
          case FlowSolverParameters::Turbulence::k_epsilon_launder_sharma: return "Launder-Sharma k-epsilon";
          case FlowSolverParameters::Turbulence::k_omega_sst: return "k-omega SST";
          default: return "laminar";
        }
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
    EXPECT_CHECK_AT_MOST("start-up of creeping pipe flow, 32 x 20, dt 0.01 R^2/nu: largest |Q/Q_inf - exact|, "
                         "t = 0.05-0.4 R^2/nu",
                         largest, 2e-3, "Szymanski (1932)");
    EXPECT_CHECK_ABSOLUTE("the same at t = 0.2 R^2/nu: observed order in time, dt 0.01, 0.005, 0.0025 R^2/nu", order, 2,
                          0.3, "BDF2");
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
    // every step meets its tolerance but the first, from rest (after 500 iterations its continuity
    // residual is still 2.6e-7: the flow has to start up), which the next steps make good
    unsigned int converged = 0;
    bool first_converged = false;
    for (int step = 0; step < 40; ++step)
      {
        const bool c = marched.advance(0.1, 500, 1e-9).converged;
        EXPECT_EQ(c, step > 0) << "step " << step;
        converged += c;
        first_converged = first_converged || (c && step == 0);
      }
    test::record_check("40 steps from rest, 500 iterations a step: steps that report they converged",
                       "39, not the first (from rest, capped)", "exact",
                       std::to_string(converged) + (first_converged ? ", the first among them" : ", not the first"));
    const double Q = marched.flow_rate("right") / steady.flow_rate("right") - 1;
    std::printf("marched to t = 4 R^2/nu: Q/Q_steady - 1 = %.2e\n", Q);
    EXPECT_CHECK_ABSOLUTE("pipe 16 x 10 marched to t = 4 R^2/nu: Q/Q_steady - 1", Q, 0, 1e-6, "the steady solver");
  }

  // A step its iteration cap stops says so: from rest, one iteration does not bring the start-up
  // step's equations to 1e-12 (the flow has to go from nothing to a tenth of Poiseuille's); the
  // same step given its iterations does reach its tolerance.
  TEST(FlowTimeStepping, SaysWhenTheIterationCapStoppedAStep)
  {
    const FvMesh mesh = rectangle(Geometry::axisymmetric, 0, L, 0, R, 8, 4);
    SimplecSolver capped(mesh, {rho, mu}, pipe, settings()), free(mesh, {rho, mu}, pipe, settings());
    const SolveReport stopped = capped.advance(0.01, 1, 1e-12);
    EXPECT_EQ(stopped.iterations, 1u);
    EXPECT_FALSE(stopped.converged);
    test::record_check("a step from rest capped at 1 iteration, tolerance 1e-12: reports it converged", "no", "exact",
                       stopped.converged ? "yes" : "no");
    const SolveReport solved = free.advance(0.01, 500, 1e-9);
    EXPECT_LT(solved.iterations, 500u);
    EXPECT_TRUE(solved.converged);
    test::record_check("the same step given 500 iterations, tolerance 1e-9: reports it converged", "yes", "exact",
                       solved.converged ? "yes" : "no");
  }

  // In a time step a liquid cell's mass balance holds the change of its mass since the old levels
  // (flow/fv/continuity.h): a cell whose old levels held vapour and that is liquid now must take in
  // rho V (new_weight - old_mass)/dt, the collapsed vapour's volume. Without that term the pressure
  // correction drove its fluxes to balance while the liquid fraction kept the old mass, and cavitating
  // steps stopped at their cap with continuity at a fixed 2e-4-7e-4 (doc/changes.md, issue 28:
  // what drives k negative in Launder-Sharma's cases).
  // Closed forms, no fluxes: implicit Euler rho V (1 - m_n)/dt; BDF2 rho V (3/2 - 2 m_n + m_n-1/2)/dt;
  // nothing for a cell liquid at every level, for a cavitating cell (its liquid fraction balances
  // its mass) and for a steady iteration.
  TEST(FlowTimeStepping, CollapsedVapourIsMassALiquidCellTakesIn)
  {
    const FvMesh mesh = rectangle(Geometry::axisymmetric, 0, 1e-3, 0, 1e-3, 3, 1);
    CavitationModel cavitation(mesh, 1e-3);
    cavitation.enable(-1e5);
    std::vector<double> p(mesh.n_cells(), 0.0);
    cavitation.set_cell_pressure(p, 2, -2e5); // cell 2 cavitates (below p_cav)
    ASSERT_TRUE(cavitation.cell_cavitates(2));
    const std::vector<double> no_flux(mesh.n_faces(), 0.0);
    TimeLevel euler;
    euler.dt = 1e-6;
    euler.last.mixture = {0.4, 1.0, 0.4};
    const double density = 850;
    const std::vector<double> first = cell_mass_imbalance(mesh, no_flux, cavitation, &euler, density);
    EXPECT_CHECK_RELATIVE("mass a liquid cell takes in, vapour at the last level, implicit Euler [kg/s]", first[0],
                          density * mesh.cell_volume[0] * (1 - 0.4) / euler.dt, 1e-12, "rho V (1 - m^n)/dt");
    TimeLevel bdf2 = euler;
    bdf2.before.u.assign(mesh.n_cells(), 0.0);
    bdf2.before.mixture = {0.7, 1.0, 0.4};
    const std::vector<double> second = cell_mass_imbalance(mesh, no_flux, cavitation, &bdf2, density);
    EXPECT_CHECK_RELATIVE("the same, BDF2 [kg/s]", second[0],
                          density * mesh.cell_volume[0] * (1.5 - 2 * 0.4 + 0.5 * 0.7) / bdf2.dt, 1e-12,
                          "rho V (3/2 - 2 m^n + 1/2 m^(n-1))/dt");
    // nothing for a cell liquid at every level, a cavitating cell, a steady iteration
    double largest = larger(larger(std::abs(first[1]), std::abs(first[2])), std::abs(second[1]));
    for (double m : cell_mass_imbalance(mesh, no_flux, cavitation))
      largest = larger(largest, std::abs(m));
    EXPECT_CHECK_ABSOLUTE("the same, a cell liquid at every level, a cavitating cell, a steady iteration [kg/s]",
                          largest, 0, 0, "nothing");
  }

  TEST(FlowTimeStepping, RefusesBadSteps)
  {
    const FvMesh mesh = rectangle(Geometry::axisymmetric, 0, L, 0, R, 8, 4);
    SimplecSolver laminar(mesh, {rho, mu}, pipe, settings());
    EXPECT_THROW(laminar.advance(0, 10, 1e-6), std::invalid_argument);
    EXPECT_THROW(laminar.advance(-1, 10, 1e-6), std::invalid_argument);
    EXPECT_THROW(laminar.courant_time_step(1), std::invalid_argument); // at rest: no flow to set it by
  }

  // Decay of homogeneous turbulence, the turbulence models' time terms (URANS): uniform flow U = 1
  // m/s through a planar channel (length 1 m, symmetry planes on both sides: no wall, no shear, so
  // no production and no diffusion), the turbulence everywhere at t = 0 that the inlet brings (I 10
  // %, L 10 mm: k0 = 0.015 m^2/s^2, epsilon0 = C_mu^(3/4) k0^(3/2)/L = 0.030 m^2/s^3, k0/epsilon0 =
  // 0.5 s). Until the inlet's fresh fluid arrives (x = U t), the cells decay in time alone:
  //   k-epsilon (two-layer, Launder-Sharma: far from walls, Re_t 7 000, standard):
  //     dk/dt = -epsilon, de/dt = -C2 e^2/k: k = k0 (1 + (C2 - 1) t/tau0)^(-1/(C2 - 1))
  //   SST (F1 = 0 without walls: the outer set, beta_2 = 0.0828):
  //     dk/dt = -beta* k w, dw/dt = -beta_2 w^2: k = k0 (1 + beta_2 w0 t)^(-beta*/beta_2)
  // k of the outlet cell at t = 0.25 and 0.5 s (the front, diffused by upwind convection over a few
  // cells, is at 0.5 m by then) at dt = 5 ms (tau0/100): BDF2's error, of order (dt/tau0)^2, is
  // about 1e-4; within 2e-4 of the closed form. At dt = 10 ms the error must be at least 3x that
  // at 5 ms (second order: 4x; first order would give 2x).
  class TurbulenceDecay : public ::testing::TestWithParam<FlowSolverParameters::Turbulence>
  {};

  TEST_P(TurbulenceDecay, FollowsTheClosedForm)
  {
    using Turbulence = FlowSolverParameters::Turbulence;
    const double U = 1, rho_air = 1, mu_small = 1e-6, intensity = 0.1, length = 0.01;
    const FvMesh mesh = rectangle(Geometry::planar, 0, 1, 0, 0.05, 100, 2);
    BoundaryCondition inlet = BoundaryCondition::velocity_inlet([&](const Vector2 &) { return Vector2(U, 0); });
    inlet.turbulence_intensity = intensity, inlet.turbulence_length = length;
    const std::map<std::string, BoundaryCondition> channel{{"left", inlet},
                                                           {"right", BoundaryCondition::pressure_outlet(0)},
                                                           {"top", BoundaryCondition::symmetry()},
                                                           {"bottom", BoundaryCondition::symmetry()}};
    const double C_mu = 0.09, k0 = 1.5 * std::pow(intensity * U, 2), epsilon0 = std::pow(C_mu, 0.75) * std::pow(k0, 1.5) / length;
    const double omega0 = epsilon0 / (C_mu * k0), C2 = 1.92, beta_2 = 0.0828;
    auto closed_form = [&](double t) {
      return GetParam() == Turbulence::k_omega_sst ? k0 * std::pow(1 + beta_2 * omega0 * t, -C_mu / beta_2) :
                                                     k0 * std::pow(1 + (C2 - 1) * t * epsilon0 / k0, -1 / (C2 - 1));
    };
    // the uniform flow, then the turbulence set on it
    SimplecSolver laminar(mesh, {rho_air, mu_small}, channel, settings());
    laminar.solve();
    FlowFields start = laminar.fields();
    start.turbulent = true;
    start.k.assign(mesh.n_cells(), k0);
    start.epsilon.assign(mesh.n_cells(), epsilon0);
    start.turbulent_viscosity.assign(mesh.n_cells(), rho_air * C_mu * k0 * k0 / epsilon0);
    // the cell at the outlet
    std::size_t outlet_cell = 0;
    for (std::size_t c = 0; c < mesh.n_cells(); ++c)
      if (mesh.cell_center[c].x() > mesh.cell_center[outlet_cell].x())
        outlet_cell = c;

    auto errors = [&](double dt) {
      auto s = settings(1e-10);
      s.turbulence = GetParam();
      SimplecSolver solver(mesh, {rho_air, mu_small}, channel, s);
      solver.set_fields(start);
      std::vector<double> e;
      double t = 0;
      for (double check : {0.25, 0.5})
        {
          while (t < check - 1e-9)
            solver.advance(dt, 200, 1e-10), t += dt;
          e.push_back(solver.fields().k[outlet_cell] / closed_form(t) - 1);
          std::printf("dt %.3f s, t %.2f s: k/k0 %.6f, closed form %.6f, error %.2e\n", dt, t,
                      solver.fields().k[outlet_cell] / k0, closed_form(t) / k0, e.back());
        }
      return e;
    };
    const std::vector<double> fine = errors(0.005), coarse = errors(0.01);
    double largest = 0, smallest_ratio = 1e300; // over t = 0.25 and 0.5 s
    for (std::size_t i = 0; i < fine.size(); ++i)
      {
        largest = larger(largest, std::abs(fine[i]));
        smallest_ratio = smaller(smallest_ratio, std::abs(coarse[i]) / std::abs(fine[i]));
      }
    const std::string model = std::string("decay of homogeneous turbulence, ") + label(GetParam());
    const char *exact = GetParam() == Turbulence::k_omega_sst ? "k0 (1 + beta_2 w0 t)^(-beta*/beta_2)" :
                                                                "k0 (1 + (C2 - 1) t/tau0)^(-1/(C2 - 1))";
    EXPECT_CHECK_AT_MOST(model + ": largest |k/k_exact - 1| at the outlet, t = 0.25, 0.5 s, dt = tau0/100", largest,
                         2e-4, exact);
    EXPECT_CHECK_AT_LEAST(model + ": error at dt x 2 / error at dt (the smaller of the two times)", smallest_ratio, 3,
                          "second order: 4");
  }

  INSTANTIATE_TEST_SUITE_P(Models, TurbulenceDecay,
                           ::testing::Values(FlowSolverParameters::Turbulence::k_epsilon,
                                             FlowSolverParameters::Turbulence::k_epsilon_launder_sharma,
                                             FlowSolverParameters::Turbulence::k_omega_sst),
                           [](const auto &info) { return test_name(info.param); });

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
    // the axis cell's u is the parabola's mean over the cell
    EXPECT_CHECK_RELATIVE("Courant time step of the developed pipe, 16 x 10 [s]", dt, dx / u_axis, 0.1,
                          "dx/u on the axis");
  }
} // namespace servodrift::flow
