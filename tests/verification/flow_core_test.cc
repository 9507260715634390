// Verification of the finite-volume solver core (flow/fv/fv_mesh, flow/fv/simplec) against closed forms
// and published data, issue 4. Tolerances are the issue's; doc/validation.md shows the checks the
// tests record (tests/support/checks.h).
//
// - plane Poiseuille and axisymmetric Hagen-Poiseuille flow: pressure drop and velocity profile
//   within 0.5 % on the default mesh, and second-order convergence (observed rate > 1.8 between
//   the three meshes; the schemes are formally second order, so 2 is expected and 1.8 leaves room
//   for the pre-asymptotic coarse mesh);
// - the lid-driven cavity at Re 100 and 400 against Ghia, Ghia and Shin (1982), within 2 % of the
//   lid velocity;
// - creeping radial outflow between parallel discs: dp = 6 mu Q ln(r2/r1)/(pi h^3) within 1 %;
// - mass conservation of the converged fields; symmetry planes, total-pressure inlets, triangles;
// - VTU output read back with VTK's reader (bad input and failing runs: flow_solver_control_test.cc).
#include "common/error.h"
#include "common/gmsh_mesh.h"
#include "common/output_files.h"
#include "common/units.h"
#include "flow/fv/field_transfer.h"
#include "flow/fv/fv_mesh.h"
#include "flow/fv/simplec.h"
#include "tests/support/checks.h"
#include "tests/support/test_support.h"
#include "tests/verification/flow_test_domains.h"

#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace servodrift::flow
{
  using namespace domains;

  namespace
  {
    const std::string source_dir = SERVODRIFT_SOURCE_DIR;


    /// Second-order reconstruction of a cell field at x: the nearest cell's value plus its
    /// least-squares gradient (boundary values from the solver).
    struct Sampler
    {
      const FvMesh &mesh;
      std::vector<double> value;
      std::vector<Vector2> gradient;
      Sampler(const FvMesh &m, const std::vector<double> &cells, const std::vector<double> &boundary)
        : mesh(m), value(cells), gradient(m.gradient(cells, boundary))
      {}
      double operator()(const Vector2 &x) const
      {
        std::size_t best = 0;
        for (std::size_t c = 1; c < mesh.n_cells(); ++c)
          if ((mesh.cell_center[c] - x).squaredNorm() < (mesh.cell_center[best] - x).squaredNorm())
            best = c;
        return value[best] + gradient[best].dot(x - mesh.cell_center[best]);
      }
    };

    std::vector<double> boundary_component(const SimplecSolver &s, const FvMesh &mesh, int component)
    {
      std::vector<double> b(mesh.n_faces(), 0.0);
      for (std::size_t f = 0; f < mesh.n_faces(); ++f)
        if (mesh.neighbour[f] < 0)
          b[f] = s.boundary_velocity(f)[component];
      return b;
    }

    /// Fully developed laminar flow through a channel (planar, walls at y = 0 and H) or a pipe
    /// (axisymmetric, axis at r = 0, wall at r = R = H), mean velocity U, length L, parabolic inlet.
    struct DevelopedFlowResult
    {
      double pressure_drop_error; ///< relative to the closed form
      double profile_error;       ///< rms of u - u_exact over the cells at mid-length, / u_max
      double net_imbalance, max_cell_imbalance;
      unsigned int iterations;
    };

    DevelopedFlowResult developed_flow(Geometry geometry, int nx, int ny, bool triangles = false)
    {
      const double L = 4, H = 1, U = 1, mu = 0.05, rho = 1; // Re = rho U H / mu = 20
      const bool pipe = geometry == Geometry::axisymmetric;
      const FvMesh mesh = rectangle(geometry, 0, L, 0, H, nx, ny, triangles);
      auto exact = [&](double y) { return pipe ? 2 * U * (1 - y * y / (H * H)) : 6 * U * y * (H - y) / (H * H); };
      std::map<std::string, BoundaryCondition> bc{
        {"left", BoundaryCondition::velocity_inlet([&](const Vector2 &x) { return Vector2(exact(x.y()), 0); })},
        {"right", BoundaryCondition::pressure_outlet(0)},
        {"top", BoundaryCondition::wall()},
        {"bottom", pipe ? BoundaryCondition::axis() : BoundaryCondition::wall()}};
      SimplecSolver solver(mesh, {rho, mu}, bc, settings());
      const SolveReport report = solver.solve();
      // E: dp = 12 mu U L / H^2 (channel), 8 mu U L / R^2 (Hagen-Poiseuille)
      const double dp_exact = (pipe ? 8 : 12) * mu * U * L / (H * H);
      const double dp = solver.mean_pressure("left") - solver.mean_pressure("right");
      // profile at mid-length, sampled on a line of points
      Sampler u(mesh, solver.velocity_x(), boundary_component(solver, mesh, 0));
      double sum = 0;
      const int samples = 50;
      for (int k = 0; k < samples; ++k)
        {
          const double y = (k + 0.5) / samples * H;
          sum += std::pow(u(Vector2(L / 2, y)) - exact(y), 2);
        }
      return {dp / dp_exact - 1, std::sqrt(sum / samples) / exact(pipe ? 0 : H / 2), solver.net_imbalance(),
              solver.max_cell_imbalance(), report.iterations};
    }

    void expect_second_order(Geometry geometry, const std::string &name)
    {
      const int nx[3] = {40, 80, 160}, ny[3] = {10, 20, 40};
      DevelopedFlowResult r[3];
      for (int k = 0; k < 3; ++k)
        r[k] = developed_flow(geometry, nx[k], ny[k]);
      std::printf("%s: cells | dp error | rate | profile error | rate\n", name.c_str());
      for (int k = 0; k < 3; ++k)
        std::printf("  %5d | %10.3e | %4.2f | %10.3e | %4.2f\n", nx[k] * ny[k], r[k].pressure_drop_error,
                    k ? std::log2(std::abs(r[k - 1].pressure_drop_error / r[k].pressure_drop_error)) : 0.0,
                    r[k].profile_error, k ? std::log2(r[k - 1].profile_error / r[k].profile_error) : 0.0);
      for (int k = 1; k < 3; ++k)
        {
          const std::string meshes = std::to_string(nx[k - 1]) + " x " + std::to_string(ny[k - 1]) + " to " +
                                     std::to_string(nx[k]) + " x " + std::to_string(ny[k]);
          EXPECT_CHECK_AT_LEAST(name + ": observed order of the dp error, " + meshes,
                                std::log2(std::abs(r[k - 1].pressure_drop_error / r[k].pressure_drop_error)), 1.8,
                                "second-order schemes");
          EXPECT_CHECK_AT_LEAST(name + ": observed order of the profile error, " + meshes,
                                std::log2(r[k - 1].profile_error / r[k].profile_error), 1.8, "second-order schemes");
        }
    }
  } // namespace

  // The default verification mesh: 128 x 32 square cells over L = 4 H. The pressure drop's error is
  // that of the wall shear of the wall cells, second order: -0.51 % with 20 cells across, so 32.
  TEST(FlowCore, PlanePoiseuilleWithinHalfAPercent)
  {
    const DevelopedFlowResult r = developed_flow(Geometry::planar, 128, 32);
    std::printf("channel 128x32: dp error %.3e, profile error %.3e, %u iterations\n", r.pressure_drop_error,
                r.profile_error, r.iterations);
    EXPECT_CHECK_ABSOLUTE("plane Poiseuille 128 x 32: dp/dp_exact - 1", r.pressure_drop_error, 0, 5e-3,
                          "dp = 12 mu U L/H^2");
    EXPECT_CHECK_AT_MOST("plane Poiseuille 128 x 32: profile error rms(u - u_exact)/u_max", r.profile_error, 5e-3,
                         "u = 6U y(H-y)/H^2");
  }

  TEST(FlowCore, HagenPoiseuilleWithinHalfAPercent)
  {
    const DevelopedFlowResult r = developed_flow(Geometry::axisymmetric, 128, 32);
    std::printf("pipe 128x32: dp error %.3e, profile error %.3e, %u iterations\n", r.pressure_drop_error,
                r.profile_error, r.iterations);
    EXPECT_CHECK_ABSOLUTE("Hagen-Poiseuille 128 x 32: dp/dp_exact - 1", r.pressure_drop_error, 0, 5e-3,
                          "dp = 8 mu U L/R^2");
    EXPECT_CHECK_AT_MOST("Hagen-Poiseuille 128 x 32: profile error rms(u - u_exact)/u_max", r.profile_error, 5e-3,
                         "u = 2U(1 - r^2/R^2)");
  }

  TEST(FlowCore, PoiseuilleConvergesAtSecondOrder)
  {
    expect_second_order(Geometry::planar, "channel");
  }

  TEST(FlowCore, HagenPoiseuilleConvergesAtSecondOrder)
  {
    expect_second_order(Geometry::axisymmetric, "pipe");
  }

  // Continuity: the SIMPLEC correction makes the fluxes conservative to the pressure solve's
  // tolerance (1e-12), so the limits of the issue (global 1e-10, cell 1e-8 of the throughput) hold
  // with room.
  TEST(FlowCore, ConvergedFieldsConserveMass)
  {
    double net = 0, cell = 0; // the larger of the channel's and the pipe's
    for (Geometry g : {Geometry::planar, Geometry::axisymmetric})
      {
        const DevelopedFlowResult r = developed_flow(g, 40, 10);
        std::printf("imbalance: net %.2e, largest cell %.2e\n", r.net_imbalance, r.max_cell_imbalance);
        net = test::larger(net, r.net_imbalance);
        cell = test::larger(cell, r.max_cell_imbalance);
      }
    EXPECT_CHECK_AT_MOST("channel and pipe 40 x 10: net mass flux out / throughput", net, 1e-10, "continuity");
    EXPECT_CHECK_AT_MOST("channel and pipe 40 x 10: largest cell imbalance / throughput", cell, 1e-8, "continuity");
  }

  // Unstructured triangles: every face non-orthogonal to its centre line, so the non-orthogonal
  // correction and the least-squares gradients carry the accuracy. 1 % on a mesh of the same size
  // as the quadrilateral default, and the error falls as the mesh is refined.
  TEST(FlowCore, PoiseuilleOnTriangles)
  {
    const DevelopedFlowResult coarse = developed_flow(Geometry::planar, 40, 10, true);
    const DevelopedFlowResult fine = developed_flow(Geometry::planar, 80, 20, true);
    std::printf("channel, triangles: dp error %.3e -> %.3e, profile error %.3e -> %.3e\n", coarse.pressure_drop_error,
                fine.pressure_drop_error, coarse.profile_error, fine.profile_error);
    EXPECT_CHECK_ABSOLUTE("channel on triangles, 80 x 20 size: dp/dp_exact - 1", fine.pressure_drop_error, 0, 1e-2,
                          "dp = 12 mu U L/H^2");
    EXPECT_CHECK_AT_MOST("channel on triangles, 80 x 20 size: profile error rms(u - u_exact)/u_max", fine.profile_error,
                         1e-2, "u = 6U y(H-y)/H^2");
    EXPECT_CHECK_AT_MOST("channel on triangles: profile error 80 x 20 size / 40 x 10 size",
                         fine.profile_error / coarse.profile_error, 1, "falls as the mesh is refined");
    EXPECT_CHECK_AT_MOST("channel on triangles, 80 x 20 size: largest cell imbalance / throughput",
                         fine.max_cell_imbalance, 1e-8, "continuity");
  }

  // A symmetry plane at y = 0 of a half channel gives the whole channel's pressure drop.
  TEST(FlowCore, SymmetryPlaneHalvesTheChannel)
  {
    const double L = 4, H = 1, U = 1, mu = 0.05;
    const FvMesh mesh = rectangle(Geometry::planar, 0, L, 0, H / 2, 128, 16);
    std::map<std::string, BoundaryCondition> bc{
      {"left", BoundaryCondition::velocity_inlet([&](const Vector2 &x) { return Vector2(6 * U * x.y() * (H - x.y()) / (H * H), 0); })},
      {"right", BoundaryCondition::pressure_outlet(0)},
      {"top", BoundaryCondition::symmetry()},
      {"bottom", BoundaryCondition::wall()}};
    // the plane of symmetry at y = H/2 is the top
    SimplecSolver solver(mesh, {1, mu}, bc, settings());
    solver.solve();
    const double dp = solver.mean_pressure("left") - solver.mean_pressure("right");
    std::printf("half channel with a symmetry plane: dp error %.3e\n", dp / (12 * mu * U * L / (H * H)) - 1);
    EXPECT_CHECK_ABSOLUTE("half channel 128 x 16, symmetry plane at the centre-line: dp/dp_exact - 1",
                          dp / (12 * mu * U * L / (H * H)) - 1, 0, 5e-3, "the whole channel's 12 mu U L/H^2");
  }

  // A total-pressure inlet: creeping pipe flow (Re = 1e-3, so the dynamic pressure is 1e-5 of the
  // drop) driven by p0 - p_out carries the Hagen-Poiseuille flow rate pi R^4 dp / (8 mu L).
  TEST(FlowCore, TotalPressureInletCarriesTheHagenPoiseuilleFlow)
  {
    const double L = 4, R = 1, mu = 1, rho = 1e-3, dp = 8 * mu * 1 * L / (R * R); // U = 1
    const FvMesh mesh = rectangle(Geometry::axisymmetric, 0, L, 0, R, 40, 20);
    std::map<std::string, BoundaryCondition> bc{{"left", BoundaryCondition::total_pressure_inlet(dp)},
                                                {"right", BoundaryCondition::pressure_outlet(0)},
                                                {"top", BoundaryCondition::wall()},
                                                {"bottom", BoundaryCondition::axis()}};
    SimplecSolver solver(mesh, {rho, mu}, bc, settings());
    solver.solve();
    const double Q = solver.flow_rate("right");
    const double Q_exact = units::pi * std::pow(R, 4) * dp / (8 * mu * L);
    std::printf("total-pressure inlet: Q/Q_HP - 1 = %.3e\n", Q / Q_exact - 1);
    EXPECT_CHECK_ABSOLUTE("creeping pipe flow from a total-pressure inlet, Re 1e-3: Q/Q_exact - 1", Q / Q_exact - 1, 0,
                          5e-3, "Q = pi R^4 dp/(8 mu L)");
    EXPECT_NEAR(solver.flow_rate("left") / Q, -1, 1e-10);
  }

  // A total-pressure inlet at Re = 200 with Bernoulli's answer: plug flow through a duct with slip
  // walls (symmetry) and no shear, so p0 - p_out = rho U^2/2 and Q = pi R^2 sqrt(2 (p0 - p_out)/rho)
  // exactly; the dynamic head is the whole drop. 0.5 %. (This frictionless flow between two pressure
  // boundaries is the hardest case for the coupling: with no pressure relaxation the iteration
  // settles into a two-iteration cycle; the default 0.7 converges it.)
  TEST(FlowCore, TotalPressureInletFollowsBernoulli)
  {
    const double L = 2, R = 1, mu = 0.01, rho = 1, p0 = 0.5; // U = 1, Re = rho U 2R / mu = 200
    const FvMesh mesh = rectangle(Geometry::axisymmetric, 0, L, 0, R, 40, 20);
    std::map<std::string, BoundaryCondition> bc{{"left", BoundaryCondition::total_pressure_inlet(p0)},
                                                {"right", BoundaryCondition::pressure_outlet(0)},
                                                {"top", BoundaryCondition::symmetry()},
                                                {"bottom", BoundaryCondition::axis()}};
    SimplecSolver solver(mesh, {rho, mu}, bc, settings());
    const SolveReport report = solver.solve();
    const double Q = solver.flow_rate("right"), Q_exact = units::pi * R * R * std::sqrt(2 * p0 / rho);
    std::printf("total-pressure inlet, Bernoulli: Q/Q_exact - 1 = %.3e (%u iterations)\n", Q / Q_exact - 1, report.iterations);
    EXPECT_CHECK_ABSOLUTE("total-pressure inlet, frictionless duct, Re 200: Q/Q_exact - 1", Q / Q_exact - 1, 0, 5e-3,
                          "Bernoulli: Q = pi R^2 sqrt(2 p0/rho)");
    EXPECT_LT(solver.max_cell_imbalance(), 1e-8);
  }

  // The coupled pressure-velocity solver (`Pressure-velocity coupling = coupled') solves the same
  // discrete equations as SIMPLEC, so it must land on the same fields: through a pipe (velocity inlet,
  // pressure outlet) and in the closed lid-driven cavity (one cell's continuity replaced by its
  // pressure). Both converge to scaled residuals of 1e-8, so the fields agree to about that, relative
  // to the largest velocity: 1e-6 leaves room for the two iterations' different last steps.
  TEST(FlowCore, CoupledSolverLandsOnSimplecsFields)
  {
    auto compare = [](const FvMesh &mesh, const std::map<std::string, BoundaryCondition> &bc, const FluidProperties &fluid,
                      const char *name) {
      FlowSolverParameters segregated = settings(), coupled = settings();
      segregated.coupling = FlowSolverParameters::Coupling::simplec;
      coupled.coupling = FlowSolverParameters::Coupling::coupled;
      SimplecSolver a(mesh, fluid, bc, segregated), b(mesh, fluid, bc, coupled);
      const SolveReport ra = a.solve(), rb = b.solve();
      double largest = 0, difference = 0;
      for (std::size_t c = 0; c < mesh.n_cells(); ++c)
        {
          largest = std::max(largest, std::hypot(a.velocity_x()[c], a.velocity_y()[c]));
          difference = std::max({difference, std::abs(a.velocity_x()[c] - b.velocity_x()[c]),
                                 std::abs(a.velocity_y()[c] - b.velocity_y()[c])});
        }
      std::printf("%s: SIMPLEC %u iterations, coupled %u; largest velocity difference %.2e of the largest velocity\n", name,
                  ra.iterations, rb.iterations, difference / largest);
      EXPECT_CHECK_AT_MOST(std::string(name) + ": largest velocity difference, coupled - SIMPLEC, / largest speed",
                           difference / largest, 1e-6, "SIMPLEC's fields");
      if (b.throughput() > 0) // relative to the inflow: not for the closed cavity
        {
          EXPECT_LT(b.max_cell_imbalance(), 1e-8) << name;
        }
    };
    const double U = 1, R = 1;
    compare(rectangle(Geometry::axisymmetric, 0, 4, 0, R, 80, 20),
            pipe_boundaries(BoundaryCondition::velocity_inlet(
              [&](const Vector2 &x) { return Vector2(2 * U * (1 - x.y() * x.y() / (R * R)), 0); })),
            {1, 0.01}, "pipe, Re 200");
    compare(rectangle(Geometry::planar, 0, 1, 0, 1, 24, 24),
            {{"top", BoundaryCondition::wall(Vector2(1, 0))},
             {"left", BoundaryCondition::wall()},
             {"right", BoundaryCondition::wall()},
             {"bottom", BoundaryCondition::wall()}},
            {1, 0.01}, "cavity, Re 100");
  }

  // The flapper land in miniature: creeping radial outflow between parallel discs, x across the
  // gap h, r from r1 (inlet, the lubrication profile) to r2 (outlet). The profile
  // v_r = 6 Q/(2 pi r h) (z/h)(1 - z/h) solves the Stokes equations exactly (the hoop term cancels
  // the 1/r part of the Laplacian), so dp = 6 mu Q ln(r2/r1)/(pi h^3); tolerance 1 % (the issue's).
  // Dimensions of RV-1's land (r1 = D_N/2, r2 = D_land/2, h = x0), Reynolds number 1e-3.
  TEST(FlowCore, RadialOutflowBetweenDiscs)
  {
    const double h = 40e-6, r1 = 0.20e-3, r2 = 0.35e-3, mu = 0.01, rho = 850;
    const double Re = 1e-3;                              // rho V h / mu at the inlet, V the mean velocity
    const double Q = Re * mu / rho * 2 * units::pi * r1; // V = Re mu / (rho h) through 2 pi r1 h
    const FvMesh mesh = rectangle(Geometry::axisymmetric, 0, h, r1, r2, 32, 48); // 32 cells across the gap
    std::map<std::string, BoundaryCondition> bc{
      {"bottom", BoundaryCondition::velocity_inlet([&](const Vector2 &x) {
         const double z = x.x() / h;
         return Vector2(0, 6 * Q / (2 * units::pi * x.y() * h) * z * (1 - z));
       })},
      {"top", BoundaryCondition::pressure_outlet(0)},
      {"left", BoundaryCondition::wall()},
      {"right", BoundaryCondition::wall()}};
    SimplecSolver solver(mesh, {rho, mu}, bc, settings());
    solver.solve();
    // the flow rate the inlet faces carry (the midpoint rule on the parabola: 1e-3 above Q)
    const double Q_inlet = -solver.flow_rate("bottom");
    const double dp = solver.mean_pressure("bottom") - solver.mean_pressure("top");
    const double dp_exact = 6 * mu * Q_inlet * std::log(r2 / r1) / (units::pi * std::pow(h, 3));
    std::printf("radial outflow: Q %.4e m^3/s, dp %.6g Pa, closed form %.6g Pa, error %.3e\n", Q_inlet, dp, dp_exact,
                dp / dp_exact - 1);
    EXPECT_CHECK_ABSOLUTE("radial outflow: Q of the inlet faces / nominal Q - 1", Q_inlet / Q - 1, 0, 2e-3,
                          "the midpoint rule on the parabola");
    EXPECT_NEAR(solver.flow_rate("top") / Q_inlet, 1, 1e-10);
    EXPECT_CHECK_ABSOLUTE("radial outflow between discs, h 40 um, r 0.20-0.35 mm, 32 x 48, Re 1e-3: dp/dp_exact - 1",
                          dp / dp_exact - 1, 0, 1e-2, "dp = 6 mu Q ln(r2/r1)/(pi h^3)");
  }

  namespace
  {
    struct GhiaPoint
    {
      char table; // u or v
      double coordinate, velocity;
      bool use;
    };

    std::vector<GhiaPoint> ghia(int re)
    {
      std::ifstream in(source_dir + "/tests/verification/data/ghia1982.txt");
      std::vector<GhiaPoint> points;
      std::string line;
      while (std::getline(in, line))
        {
          if (line.empty() || line[0] == '#')
            continue;
          std::istringstream s(line);
          GhiaPoint p;
          int r, use;
          s >> p.table >> r >> p.coordinate >> p.velocity >> use;
          p.use = use != 0;
          if (r == re)
            points.push_back(p);
        }
      return points;
    }

    /// Ghia's points a comparison uses (the file's published values less those it excludes).
    std::size_t used_points(int re)
    {
      const std::vector<GhiaPoint> points = ghia(re);
      return std::count_if(points.begin(), points.end(), [](const GhiaPoint &p) { return p.use; });
    }

    /// Largest deviation from Ghia's centre-line velocities, in lid velocities (unit cavity, U = 1).
    double cavity_deviation(int re, int n,
                            FlowSolverParameters::Convection convection = FlowSolverParameters::Convection::bounded_linear_upwind)
    {
      const FvMesh mesh = rectangle(Geometry::planar, 0, 1, 0, 1, n, n);
      std::map<std::string, BoundaryCondition> bc{{"top", BoundaryCondition::wall(Vector2(1, 0))},
                                                  {"left", BoundaryCondition::wall()},
                                                  {"right", BoundaryCondition::wall()},
                                                  {"bottom", BoundaryCondition::wall()}};
      FlowSolverParameters s = settings(1e-7);
      s.convection = convection;
      SimplecSolver solver(mesh, {1, 1.0 / re}, bc, s);
      const SolveReport report = solver.solve();
      Sampler u(mesh, solver.velocity_x(), boundary_component(solver, mesh, 0));
      Sampler v(mesh, solver.velocity_y(), boundary_component(solver, mesh, 1));
      double worst = 0;
      for (const GhiaPoint &g : ghia(re))
        {
          const double ours = g.table == 'u' ? u(Vector2(0.5, g.coordinate)) : v(Vector2(g.coordinate, 0.5));
          const double deviation = std::abs(ours - g.velocity);
          if (!g.use)
            std::printf("  excluded: Re %d %c(%.4f) = %.5f, Ghia %.5f\n", re, g.table, g.coordinate, ours, g.velocity);
          else
            worst = std::max(worst, deviation);
        }
      std::printf("cavity Re %d, %dx%d: %u iterations, largest deviation from Ghia %.4f U\n", re, n, n,
                  report.iterations, worst);
      return worst;
    }
  } // namespace

  TEST(FlowCore, LidDrivenCavityRe100MatchesGhia)
  {
    ASSERT_EQ(ghia(100).size(), 34u);
    EXPECT_CHECK_AT_MOST("lid-driven cavity Re 100, 64 x 64: largest deviation from Ghia's " +
                           std::to_string(used_points(100)) + " points [U]",
                         cavity_deviation(100, 64), 0.02, "Ghia et al. (1982)");
  }

  TEST(FlowCore, LidDrivenCavityRe400MatchesGhia)
  {
    ASSERT_EQ(ghia(400).size(), 34u);
    EXPECT_CHECK_AT_MOST("lid-driven cavity Re 400, 64 x 64: largest deviation from Ghia's " +
                           std::to_string(used_points(400)) + " points [U]",
                         cavity_deviation(400, 64), 0.02, "Ghia et al. (1982)");
  }

  // The paper's first-order upwind scheme stays selectable; on the same 32 x 32 mesh it departs
  // further from Ghia than the bounded linear upwind scheme (its numerical diffusion), which is why
  // the latter is the default.
  TEST(FlowCore, UpwindIsSelectableAndLessAccurate)
  {
    const double first = cavity_deviation(400, 32, FlowSolverParameters::Convection::upwind);
    const double second = cavity_deviation(400, 32);
    EXPECT_CHECK_AT_LEAST("cavity Re 400, 32 x 32: deviation from Ghia, first-order upwind / bounded linear upwind",
                          first / second, 1.5, "upwind further from Ghia");
  }

  TEST(FlowCore, VtuReadsBackWithVtk)
  {
    const FvMesh mesh = rectangle(Geometry::axisymmetric, 0, 4, 0, 1, 12, 4);
    std::map<std::string, BoundaryCondition> bc{
      {"left", BoundaryCondition::velocity_inlet([](const Vector2 &x) { return Vector2(2 * (1 - x.y() * x.y()), 0); })},
      {"right", BoundaryCondition::pressure_outlet(0)},
      {"top", BoundaryCondition::wall()},
      {"bottom", BoundaryCondition::axis()}};
    SimplecSolver solver(mesh, {1, 0.05}, bc, settings());
    solver.solve();
    const std::string file = test::temporary_directory() + "/pipe.vtu";
    solver.write_vtu(file);

    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(file.c_str());
    reader->Update();
    vtkUnstructuredGrid *grid = reader->GetOutput();
    ASSERT_NE(grid, nullptr);
    const std::size_t n_boundary = 2 * (12 + 4);
    ASSERT_EQ(static_cast<std::size_t>(grid->GetNumberOfCells()), mesh.n_cells() + n_boundary);
    vtkDataArray *p = grid->GetCellData()->GetArray("p");
    vtkDataArray *velocity = grid->GetCellData()->GetArray("velocity");
    vtkDataArray *cell_id = grid->GetCellData()->GetArray("cell_id");
    vtkDataArray *boundary_id = grid->GetCellData()->GetArray("boundary_id");
    ASSERT_TRUE(p && velocity && cell_id && boundary_id);
    EXPECT_EQ(velocity->GetNumberOfComponents(), 3);
    for (std::size_t c = 0; c < mesh.n_cells(); ++c)
      {
        EXPECT_DOUBLE_EQ(p->GetComponent(c, 0), solver.pressure()[c]);
        EXPECT_DOUBLE_EQ(velocity->GetComponent(c, 0), solver.velocity_x()[c]);
        EXPECT_DOUBLE_EQ(velocity->GetComponent(c, 1), solver.velocity_y()[c]);
        EXPECT_EQ(cell_id->GetComponent(c, 0), double(c));
        EXPECT_EQ(boundary_id->GetComponent(c, 0), -1.0);
      }
    // the boundary line cells carry their patch's id, whose name is in the field data
    auto *names = vtkStringArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray("boundary_names"));
    ASSERT_NE(names, nullptr);
    std::map<std::string, int> count;
    for (std::size_t c = mesh.n_cells(); c < mesh.n_cells() + n_boundary; ++c)
      {
        const int id = static_cast<int>(boundary_id->GetComponent(c, 0));
        ASSERT_GE(id, 0);
        ASSERT_LT(id, names->GetNumberOfValues());
        ++count[names->GetValue(id)];
      }
    EXPECT_EQ(count["left"], 4);
    EXPECT_EQ(count["right"], 4);
    EXPECT_EQ(count["top"], 12);
    EXPECT_EQ(count["bottom"], 12);
    test::record_check("VTU read back by vtkXMLUnstructuredGridReader: p, velocity, cell_id, boundary_id, patch names",
                       "the solver's fields and patches", "exact", HasFailure() ? "differs" : "the same");
  }
} // namespace servodrift::flow
