// Verification of the flow solver's control of a run (flow/fv/simplec, flow/iteration_control; issue 4):
// bad input refused with messages naming what to fix, a run that reaches its iteration limit or
// stalls fails naming why (or goes on coupled), and a diverging run stops naming its iteration with
// its fields written. The iteration control's own state machine is unit-tested
// (tests/unit/iteration_control_test.cc).
#include "common/error.h"
#include "common/units.h"
#include "flow/fv/boundary_conditions.h"
#include "flow/fv/fv_matrix.h"
#include "flow/fv/fv_mesh.h"
#include "flow/fv/simplec.h"
#include "tests/support/checks.h"
#include "tests/support/test_support.h"
#include "tests/verification/flow_test_domains.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

namespace servodrift::flow
{
  using namespace domains;

#define EXPECT_CONTAINS(text, part)                                                                            \
  do                                                                                                             \
    {                                                                                                            \
      const std::string text_ = (text);                                                                          \
      EXPECT_NE(text_.find(part), std::string::npos) << "`" << text_ << "' does not contain `" << (part) << "'"; \
  } while (false)

  namespace
  {
    template <typename F>
    std::string error_of(F &&f)
    {
      try
        {
          f();
        }
      catch (const std::exception &e)
        {
          return e.what();
        }
      return "(no error)";
    }
  } // namespace

  TEST(FlowCore, RefusesBadInput)
  {
    const FvMesh mesh = rectangle(Geometry::planar, 0, 1, 0, 1, 4, 4);
    const auto s = settings();
    const auto inlet = BoundaryCondition::velocity_inlet([](const Vector2 &) { return Vector2(1, 0); });
    using BCs = std::map<std::string, BoundaryCondition>;
    const BCs good{{"left", inlet}, {"right", BoundaryCondition::pressure_outlet(0)},
                   {"top", BoundaryCondition::wall()}, {"bottom", BoundaryCondition::wall()}};
    EXPECT_NO_THROW(SimplecSolver(mesh, {1, 1}, good, s));

    BCs no_outlet = good;
    no_outlet["right"] = BoundaryCondition::wall();
    EXPECT_CONTAINS(error_of([&] { SimplecSolver(mesh, {1, 1}, no_outlet, s); }), "no outlet");
    BCs no_inlet = good;
    no_inlet["left"] = BoundaryCondition::wall();
    EXPECT_CONTAINS(error_of([&] { SimplecSolver(mesh, {1, 1}, no_inlet, s); }), "no inlet");
    BCs unknown = good;
    unknown["outlet"] = BoundaryCondition::pressure_outlet(0);
    const std::string e = error_of([&] { SimplecSolver(mesh, {1, 1}, unknown, s); });
    EXPECT_CONTAINS(e, "rectangle.geo: no boundary `outlet'");
    EXPECT_CONTAINS(e, "bottom, left, right, top");
    BCs missing = good;
    missing.erase("top");
    EXPECT_CONTAINS(error_of([&] { SimplecSolver(mesh, {1, 1}, missing, s); }),
                    "boundary `top' has no boundary condition");
    BCs planar_axis = good;
    planar_axis["bottom"] = BoundaryCondition::axis();
    EXPECT_CONTAINS(error_of([&] { SimplecSolver(mesh, {1, 1}, planar_axis, s); }), "axis in a planar");
    EXPECT_CONTAINS(error_of([&] { SimplecSolver(mesh, {1, 0}, good, s); }), "viscosity 0 Pa*s must be > 0");
    EXPECT_CONTAINS(error_of([&] { SimplecSolver(mesh, {-1, 1}, good, s); }), "density -1 kg/m^3 must be > 0");
    for (auto fluid : {FluidProperties{1, 0}, FluidProperties{0, 1}})
      EXPECT_THROW(SimplecSolver(mesh, fluid, good, s), InputError);

    // mesh files: absent, not gmsh
    const std::string dir = test::temporary_directory();
    EXPECT_CONTAINS(error_of([&] { read_gmsh_file(dir + "/absent.msh"); }), dir + "/absent.msh");
    {
      std::ofstream(dir + "/not_gmsh.msh") << "this is not a mesh\n";
    }
    const std::string not_gmsh = error_of([&] { read_gmsh_file(dir + "/not_gmsh.msh"); });
    EXPECT_CONTAINS(not_gmsh, dir + "/not_gmsh.msh");
    EXPECT_THROW(read_gmsh_file(dir + "/not_gmsh.msh"), InputError);
    {
      std::ofstream(dir + "/not_gmsh.geo") << "this is not a geometry\n";
    }
    EXPECT_CONTAINS(error_of([&] { read_gmsh_file(dir + "/not_gmsh.geo"); }), dir + "/not_gmsh.geo: gmsh cannot read it");
    // and gmsh reads the next file: the failed parse leaves nothing behind
    EXPECT_EQ(rectangle(Geometry::planar, 0, 1, 0, 1, 3, 3).n_cells(), 9u);
    test::record_check("no inlet, no outlet, unknown or missing boundary, axis in a planar mesh, viscosity or density "
                       "<= 0, absent or non-gmsh mesh file",
                       "refused, naming what to fix", "-", HasFailure() ? "not all" : "all refused");
  }

  // An iteration limit that is too small fails the run, naming the residuals; it does not hand back
  // the unconverged fields.
  TEST(FlowCore, UnconvergedRunFails)
  {
    const FvMesh mesh = rectangle(Geometry::planar, 0, 4, 0, 1, 20, 5);
    auto s = settings();
    s.max_iterations = 5;
    std::map<std::string, BoundaryCondition> bc{
      {"left", BoundaryCondition::velocity_inlet([](const Vector2 &) { return Vector2(1, 0); })},
      {"right", BoundaryCondition::pressure_outlet(0)},
      {"top", BoundaryCondition::wall()},
      {"bottom", BoundaryCondition::wall()}};
    SimplecSolver solver(mesh, {1, 0.05}, bc, s);
    solver.failure_output = test::temporary_directory() + "/unconverged.vtu";
    const std::string e = error_of([&] { solver.solve(); });
    EXPECT_CONTAINS(e, "not converged in 5 iterations");
    EXPECT_CONTAINS(e, "tolerance 1e-08");
    EXPECT_TRUE(std::ifstream(solver.failure_output).good());
    test::record_check("iteration limit (5) reached", "the run fails naming the iterations and the residuals",
                       "-", HasFailure() ? "no" : "fails so, fields written");
  }

  // A caller may end a solve early once its answer is clear (PilotField's liquid check: clearly
  // cavitating): solve_to asks after each iteration that goes on and stops at the first yes, with
  // that iteration's residuals; a question that never says yes leaves the solve as it was.
  TEST(FlowCore, SolveStopsWhereTheCallerDecided)
  {
    const FvMesh mesh = rectangle(Geometry::planar, 0, 4, 0, 1, 20, 5);
    std::map<std::string, BoundaryCondition> bc{
      {"left", BoundaryCondition::velocity_inlet([](const Vector2 &) { return Vector2(1, 0); })},
      {"right", BoundaryCondition::pressure_outlet(0)},
      {"top", BoundaryCondition::wall()},
      {"bottom", BoundaryCondition::wall()}};
    SimplecSolver full(mesh, {1, 0.05}, bc, settings());
    unsigned int asked = 0;
    const SolveReport all = full.solve_to(1e-6, false, [&](const Residuals &) { return ++asked, false; });
    EXPECT_EQ(asked, all.iterations - 1); // not asked after the converged iteration
    EXPECT_GT(all.iterations, 10u);
    SimplecSolver early(mesh, {1, 0.05}, bc, settings());
    Residuals at_seventh;
    unsigned int count = 0;
    const SolveReport stopped = early.solve_to(1e-6, false, [&](const Residuals &r) {
      at_seventh = r;
      return ++count == 7;
    });
    EXPECT_EQ(stopped.iterations, 7u);
    EXPECT_EQ(stopped.residuals.continuity, at_seventh.continuity);
    EXPECT_GT(stopped.residuals.continuity, 1e-6);
  }

  // Without pressure relaxation SIMPLEC settles into a two-iteration cycle on the frictionless
  // Bernoulli duct (above): with `simplec' the stall test stops it; with `simplec-then-coupled' the
  // coupled iterations take over at the stall and converge to Bernoulli's flow rate (0.5 %, as above).
  TEST(FlowCore, StalledSimplecGoesOnCoupled)
  {
    const double L = 2, R = 1, mu = 0.01, rho = 1, p0 = 0.5;
    const FvMesh mesh = rectangle(Geometry::axisymmetric, 0, L, 0, R, 40, 20);
    std::map<std::string, BoundaryCondition> bc{{"left", BoundaryCondition::total_pressure_inlet(p0)},
                                                {"right", BoundaryCondition::pressure_outlet(0)},
                                                {"top", BoundaryCondition::symmetry()},
                                                {"bottom", BoundaryCondition::axis()}};
    FlowSolverParameters s = settings();
    s.pressure_relaxation = 1;
    s.cycle_window = 0;
    s.stall_window = 50;
    s.coupling = FlowSolverParameters::Coupling::simplec;
    SimplecSolver alone(mesh, {rho, mu}, bc, s);
    EXPECT_CONTAINS(error_of([&] { alone.solve(); }), "stalled");
    s.coupling = FlowSolverParameters::Coupling::simplec_then_coupled;
    SimplecSolver solver(mesh, {rho, mu}, bc, s);
    const SolveReport report = solver.solve();
    const double Q = solver.flow_rate("right"), Q_exact = units::pi * R * R * std::sqrt(2 * p0 / rho);
    std::printf("Bernoulli duct without pressure relaxation, SIMPLEC then coupled: Q/Q_exact - 1 = %.3e (%u iterations)\n",
                Q / Q_exact - 1, report.iterations);
    EXPECT_GT(report.iterations, 100u); // SIMPLEC ran until the stall test (windows of 50 from rest)
    // a run that the coupled iterations do not finish fails, and says that they ran: here the
    // iteration limit ends them one iteration short
    s.max_iterations = report.iterations - 1;
    SimplecSolver limited(mesh, {rho, mu}, bc, s);
    EXPECT_CONTAINS(error_of([&] { limited.solve(); }), "coupled iterations since SIMPLEC stalled at iteration ");
    EXPECT_CHECK_ABSOLUTE("frictionless duct without pressure relaxation, SIMPLEC then coupled: Q/Q_exact - 1",
                          Q / Q_exact - 1, 0, 5e-3, "Bernoulli: Q = pi R^2 sqrt(2 p0/rho)");
    EXPECT_LT(solver.max_cell_imbalance(), 1e-8);
  }
} // namespace servodrift::flow

namespace servodrift::flow
{
  // Without under-relaxation a cavity at Re 1e6 on a coarse mesh blows up: the run stops at the
  // iteration where a residual is no longer finite or has grown beyond 1e8, naming it, and writes
  // the fields it had for inspection.
  TEST(FlowCore, DivergenceStopsTheRun)
  {
    const FvMesh mesh = rectangle(Geometry::planar, 0, 1, 0, 1, 16, 16);
    auto s = settings();
    s.velocity_relaxation = 1;
    s.convection = FlowSolverParameters::Convection::bounded_linear_upwind;
    std::map<std::string, BoundaryCondition> bc{{"top", BoundaryCondition::wall(Vector2(1, 0))},
                                                {"left", BoundaryCondition::wall()},
                                                {"right", BoundaryCondition::wall()},
                                                {"bottom", BoundaryCondition::wall()}};
    SimplecSolver solver(mesh, {1, 1e-6}, bc, s);
    solver.failure_output = test::temporary_directory() + "/diverged.vtu";
    const std::string e = error_of([&] { solver.solve(); });
    std::printf("%s\n", e.c_str());
    EXPECT_CONTAINS(e, "diverged at iteration");
    EXPECT_TRUE(std::ifstream(solver.failure_output).good());
    test::record_check("divergence (cavity Re 1e6, no relaxation)", "the run stops naming the iteration", "-",
                       HasFailure() ? "no" : "stops so, fields written");
  }
} // namespace servodrift::flow

namespace servodrift::flow
{
  // The held convection limiter (FvMatrix::hold_limiter, which the iteration control asks for when
  // coupled iterations hover near the tolerance): while held, the bounded scheme's assembly uses the
  // limiter of the last free assembly, so that it is linear in phi (Barth-Jespersen's limiter
  // depends on phi, and the free assembly is not); released, it is the free assembly again.
  TEST(FlowCore, HeldConvectionLimiterKeepsTheValuesOfItsLastAssembly)
  {
    const FvMesh mesh = rectangle(Geometry::planar, 0, 1, 0, 1, 12, 12);
    const BoundaryConditions bc(mesh, {1, 1e-3},
                                {{"top", BoundaryCondition::wall(Vector2(1, 0))},
                                 {"left", BoundaryCondition::wall()},
                                 {"right", BoundaryCondition::wall()},
                                 {"bottom", BoundaryCondition::wall()}});
    const MatrixPattern pattern(mesh);
    const std::size_t n = mesh.n_cells();
    // a step and a wave (the limiter acts at the step and at the wave's extrema), walls at 0, a
    // uniform flux to the right and up
    std::vector<double> step(n), wave(n), sum(n), zero_b(mesh.n_faces(), 0.0), gamma(mesh.n_faces(), 1e-3),
      flux(mesh.n_faces());
    for (std::size_t c = 0; c < n; ++c)
      {
        const Vector2 &x = mesh.cell_center[c];
        step[c] = x.x() < 0.5 ? 0.0 : 1.0;
        wave[c] = std::sin(3 * units::pi * x.x()) * std::cos(2 * units::pi * x.y());
        sum[c] = step[c] + wave[c];
      }
    for (std::size_t f = 0; f < mesh.n_faces(); ++f)
      flux[f] = mesh.face_area[f] * (mesh.face_normal[f].x() + 0.5 * mesh.face_normal[f].y());
    constexpr auto bounded = FlowSolverParameters::Convection::bounded_linear_upwind;
    auto b_of = [&](FvMatrix &eq, const std::vector<double> &phi) {
      eq.assemble_convection_diffusion(phi, zero_b, gamma, flux, bc, bounded);
      return Eigen::VectorXd(eq.b);
    };
    FvMatrix free(mesh, pattern), held(mesh, pattern);
    const Eigen::VectorXd b_step = b_of(free, step), b_wave = b_of(free, wave), b_sum = b_of(free, sum);
    // the free assembly is not linear in phi (its limiter follows phi): the deferred corrections differ
    const double nonlinearity = (b_sum - b_step - b_wave).norm() / b_sum.norm();
    EXPECT_GT(nonlinearity, 1e-3);
    // held after the step's assembly: the step's limiter for the wave and for the sum, so linear
    EXPECT_LT((b_of(held, step) - b_step).norm(), 1e-14 * b_step.norm());
    held.hold_limiter(true);
    const Eigen::VectorXd held_wave = b_of(held, wave), held_sum = b_of(held, sum);
    const double held_nonlinearity = (held_sum - b_step - held_wave).norm() / held_sum.norm();
    std::printf("assembly's nonlinearity in phi: free limiter %.3e, held %.3e\n", nonlinearity, held_nonlinearity);
    EXPECT_LT(held_nonlinearity, 1e-12);
    EXPECT_GT((held_wave - b_wave).norm(), 1e-3 * b_wave.norm()); // not the wave's own limiter
    // released: the free assembly again
    held.hold_limiter(false);
    EXPECT_LT((b_of(held, wave) - b_wave).norm(), 1e-14 * b_wave.norm());
  }
} // namespace servodrift::flow
