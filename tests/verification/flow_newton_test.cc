// Newton-PTC (flow/fv/newton_flow.cc) solves the steady discrete equations of SIMPLEC as one system:
// started from SIMPLEC's own path partway (a scaled residual of 1e-2), with the limiter live it must
// land on SIMPLEC's fields converged to 1e-10 (both within about 1e-9 of the discrete solution: 1e-7
// leaves room for the different last steps), and converge to 1e-10 itself. With the limiter held
// below 1e-5 it solves the held limiter's equations: within 1e-4 (the limiter frozen at a state 1e-5
// from the solution moves the fields by up to 3e-5 here).
#include "flow/fv/simplec.h"
#include "flow_test_domains.h"
#include "tests/support/checks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

using namespace servodrift;
using namespace servodrift::flow;
using namespace servodrift::flow::domains;

namespace
{
  /// The largest velocity difference over the largest speed, and the pressure
  /// difference over the largest pressure difference in the field.
  struct Difference
  {
    double velocity, pressure;
  };
  Difference difference(const FvMesh &mesh, const SimplecSolver &a, const SimplecSolver &b)
  {
    double speed = 0, du = 0, p_min = 1e300, p_max = -1e300, dp = 0;
    for (std::size_t c = 0; c < mesh.n_cells(); ++c)
      {
        speed = std::max(speed, std::hypot(a.velocity_x()[c], a.velocity_y()[c]));
        du = std::max(
            {du, std::abs(a.velocity_x()[c] - b.velocity_x()[c]), std::abs(a.velocity_y()[c] - b.velocity_y()[c])});
        p_min = std::min(p_min, a.pressure()[c]), p_max = std::max(p_max, a.pressure()[c]);
        dp = std::max(dp, std::abs(a.pressure()[c] - b.pressure()[c]));
      }
    return {du / speed, dp / (p_max - p_min)};
  }

  /// limiter_hold: solve_newton's; tolerance: of the field differences [1]
  void lands_on_simplec(const FvMesh &mesh, const std::map<std::string, BoundaryCondition> &bc,
                        const FluidProperties &fluid, const char *name, double limiter_hold = 0,
                        double tolerance = 1e-7)
  {
    SimplecSolver reference(mesh, fluid, bc, settings(1e-10)), newton(mesh, fluid, bc, settings(1e-10));
    reference.solve();
    newton.solve_to(1e-2, false);
    const PtcReport r = newton.solve_newton({}, limiter_hold);
    std::printf("%s: %s in %u steps (%u Jacobians of %u colours, %u residuals); norm", name,
                to_string(r.outcome).c_str(), r.steps, r.jacobians, r.colours, r.residual_evaluations);
    for (double h : r.history)
      std::printf(" %.1e", h);
    const Difference d = difference(mesh, reference, newton);
    std::printf("\n  fields against SIMPLEC's: velocity %.1e, pressure %.1e\n", d.velocity, d.pressure);
    EXPECT_EQ(r.outcome, PtcOutcome::converged) << name;
    const char *source = limiter_hold > 0 ? "SIMPLEC's fields (the held limiter's equations)" : "SIMPLEC's fields";
    EXPECT_CHECK_AT_MOST(std::string(name) + ": largest velocity difference / largest speed", d.velocity, tolerance,
                         source);
    EXPECT_CHECK_AT_MOST(std::string(name) + ": largest pressure difference / pressure range", d.pressure, tolerance,
                         source);
    EXPECT_EQ(r.limiter_held, limiter_hold > 0) << name;
  }
} // namespace

TEST(FlowNewton, LandsOnSimplecsFieldsInAPipe)
{
  const double U = 1, R = 1;
  lands_on_simplec(rectangle(Geometry::axisymmetric, 0, 4, 0, R, 40, 10),
                   pipe_boundaries(BoundaryCondition::velocity_inlet(
                       [&](const Vector2 &x) { return Vector2(2 * U * (1 - x.y() * x.y() / (R * R)), 0); })),
                   {1, 0.01}, "pipe, Re 200");
}

TEST(FlowNewton, LandsOnSimplecsFieldsBetweenPressureBoundaries)
{
  lands_on_simplec(rectangle(Geometry::axisymmetric, 0, 2, 0, 1, 40, 20),
                   {{"left", BoundaryCondition::total_pressure_inlet(0.5)},
                    {"right", BoundaryCondition::pressure_outlet(0)},
                    {"top", BoundaryCondition::wall()},
                    {"bottom", BoundaryCondition::axis()}},
                   {1, 0.01}, "total-pressure inlet");
}

TEST(FlowNewton, LandsOnSimplecsFieldsInTheCavity)
{
  lands_on_simplec(rectangle(Geometry::planar, 0, 1, 0, 1, 24, 24),
                   {{"top", BoundaryCondition::wall(Vector2(1, 0))},
                    {"left", BoundaryCondition::wall()},
                    {"right", BoundaryCondition::wall()},
                    {"bottom", BoundaryCondition::wall()}},
                   {1, 0.01}, "cavity, Re 100");
}

TEST(FlowNewton, HeldLimiterLandsNearSimplecsFields)
{
  const double U = 1, R = 1;
  lands_on_simplec(rectangle(Geometry::axisymmetric, 0, 4, 0, R, 40, 10),
                   pipe_boundaries(BoundaryCondition::velocity_inlet(
                     [&](const Vector2 &x) { return Vector2(2 * U * (1 - x.y() * x.y() / (R * R)), 0); })),
                   {1, 0.01}, "pipe, Re 200, limiter held", 1e-5, 1e-4);
  lands_on_simplec(rectangle(Geometry::planar, 0, 1, 0, 1, 24, 24),
                   {{"top", BoundaryCondition::wall(Vector2(1, 0))},
                    {"left", BoundaryCondition::wall()},
                    {"right", BoundaryCondition::wall()},
                    {"bottom", BoundaryCondition::wall()}},
                   {1, 0.01}, "cavity, Re 100, limiter held", 1e-5, 1e-4);
}
