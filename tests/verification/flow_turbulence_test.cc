// Verification of the flow solver's turbulence models against correlations (issue 4, issue 28): the
// developed turbulent pipe against Blasius for every model, the viscosity bound, the turbulence
// fields in the VTU; Launder-Sharma below transition stays laminar. doc/validation.md shows the checks
// the tests record (tests/support/checks.h).
#include "common/error.h"
#include "flow/fv/fv_mesh.h"
#include "flow/fv/simplec.h"
#include "tests/support/checks.h"
#include "tests/support/test_support.h"
#include "tests/verification/flow_test_domains.h"

#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cmath>

namespace servodrift::flow
{
  using namespace domains;

  // The turbulence models (two-layer and Launder-Sharma k-epsilon, k-omega SST), integrated to the
  // wall: turbulent pipe flow at Re_D = 2e4 (uniform inlet with 5 % intensity), the pressure gradient
  // over 0.6..0.9 of the length. The friction factor against Blasius, f = 0.316 Re^-1/4: Blasius
  // itself matches measurements to about 2 % here, and low-Reynolds two-equation models are within
  // about 10 % of measured skin friction in fully developed pipe and channel flow (Patel, Rodi and
  // Scheuerer, AIAA J. 23 (1985) 1308; SST's near-wall k-omega layer is calibrated on such flows,
  // Menter 1994); hence 10 %. The pipe is 60 D long, where the flow is developed (from 30 to 60 D the
  // two-layer model's f still changes by 4 %), with 80 cells across the radius, the first at y+ 0.7:
  // SST needs y+ below 1 (at y+ 1.8 its f falls by 5 %, at 0.4 it is -0.8 % of Blasius). Launder-
  // Sharma converges there since it has Durbin's bound (without it, it stalled), and since its D is
  // linearised at the neighbours' k in a hole (a cell below 1e-5 of their mean; k_epsilon.h's
  // hole_fraction): with the e~ production of the linearised state but without that, it stalled at an
  // e~ residual of 2e-3, holes of k 1e-12 m^2/s^2 near the wall between cells of 1e-6 and 2e-4.
  struct PipeCase
  {
    FlowSolverParameters::Turbulence model;
    double length;    ///< in radii
    double nx, ny;    ///< cells along and across
  };

  class TurbulentPipe : public ::testing::TestWithParam<PipeCase>
  {};

  const char *model_label(FlowSolverParameters::Turbulence t)
  {
    switch (t)
      {
        case FlowSolverParameters::Turbulence::k_epsilon: return "two-layer";
        case FlowSolverParameters::Turbulence::k_epsilon_launder_sharma: return "Launder-Sharma";
        case FlowSolverParameters::Turbulence::k_omega_sst: return "SST";
        default: return "laminar";
      }
  }

  TEST_P(TurbulentPipe, FollowsBlasius)
  {
    const PipeCase pipe = GetParam();
    const double L = pipe.length, R = 1, U = 1, rho = 1, Re = 2e4;
    const FvMesh mesh = rectangle(Geometry::axisymmetric, 0, L, 0, R, int(pipe.nx), int(pipe.ny), false, 0.05);
    auto inlet = BoundaryCondition::velocity_inlet([&](const Vector2 &) { return Vector2(U, 0); });
    inlet.turbulence_intensity = 0.05;
    inlet.turbulence_length = 0.1 * R;
    const auto bc = pipe_boundaries(inlet);
    auto s = settings(1e-6);
    s.turbulence = pipe.model;
    SimplecSolver solver(mesh, {rho, rho * U * 2 * R / Re}, bc, s);
    const SolveReport report = solver.solve();
    // least-squares slope of the cell pressures over 0.6 L .. 0.9 L
    double sx = 0, sp = 0, sxx = 0, sxp = 0, count = 0;
    for (std::size_t c = 0; c < mesh.n_cells(); ++c)
      {
        const double x = mesh.cell_center[c].x(), p = solver.pressure()[c];
        if (x > 0.6 * L && x < 0.9 * L)
          sx += x, sp += p, sxx += x * x, sxp += x * p, ++count;
      }
    const double slope = (count * sxp - sx * sp) / (count * sxx - sx * sx);
    const double f = -slope * 2 * R / (0.5 * rho * U * U), blasius = 0.316 * std::pow(Re, -0.25);
    double largest_mu_t = 0;
    for (double m : solver.turbulent_viscosity())
      largest_mu_t = std::max(largest_mu_t, m);
    const auto y_plus = solver.wall_y_plus();
    std::printf("turbulent pipe Re %.0f (%s): f %.5f, Blasius %.5f (%+.1f %%), mu_t/mu up to %.0f, wall y+ up to %.2f, %u iterations\n",
                Re, model_label(pipe.model), f, blasius, 100 * (f / blasius - 1), largest_mu_t / (rho * U * 2 * R / Re),
                *std::max_element(y_plus.begin(), y_plus.end()), report.iterations);
    const std::string model = std::string("turbulent pipe Re_D 2e4, ") + model_label(pipe.model);
    EXPECT_CHECK_ABSOLUTE(model + ": f/f_Blasius - 1", f / blasius - 1, 0, 0.10, "Blasius f = 0.316 Re^-1/4");
    EXPECT_CHECK_AT_LEAST(model + ": largest mu_t/mu", largest_mu_t / (rho * U * 2 * R / Re), 10,
                          "turbulent, not laminar");
    EXPECT_LT(solver.max_cell_imbalance(), 1e-8);
    EXPECT_EQ(report.cells_at_viscosity_limit, 0u); // the default bound, 1e5 mu, is far away

    // a bound below the converged mu_t holds it there and is reported: that state is not the
    // model's solution (the pilot stage refuses it), and the friction factor shows it
    const double mu = rho * U * 2 * R / Re, bound = 0.5 * largest_mu_t / mu;
    solver.set_turbulent_viscosity_limit(bound);
    const SolveReport held = solver.solve();
    double held_largest = 0;
    for (double m : solver.turbulent_viscosity())
      held_largest = std::max(held_largest, m / mu);
    std::printf("  held at %.0f mu: %zu cells at the bound, mu_t/mu up to %.1f, %u iterations\n", bound,
                held.cells_at_viscosity_limit, held_largest, held.iterations);
    EXPECT_GT(held.cells_at_viscosity_limit, 0u);
    EXPECT_LE(held_largest, bound * (1 + 1e-9));

    // the VTU carries the turbulence fields
    const std::string file = test::temporary_directory() + "/turbulent_pipe.vtu";
    solver.write_vtu(file);
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(file.c_str());
    reader->Update();
    const char *rate = pipe.model == FlowSolverParameters::Turbulence::k_omega_sst ? "omega" : "epsilon";
    for (const char *name : {"k", rate, "turbulent_viscosity"})
      ASSERT_NE(reader->GetOutput()->GetCellData()->GetArray(name), nullptr) << name;
    vtkDataArray *mu_t = reader->GetOutput()->GetCellData()->GetArray("turbulent_viscosity");
    for (std::size_t c = 0; c < mesh.n_cells(); c += 97)
      EXPECT_DOUBLE_EQ(mu_t->GetComponent(c, 0), solver.turbulent_viscosity()[c]);
  }

  INSTANTIATE_TEST_SUITE_P(FlowCore, TurbulentPipe,
                           ::testing::Values(PipeCase{FlowSolverParameters::Turbulence::k_epsilon, 120, 120, 80},
                                             PipeCase{FlowSolverParameters::Turbulence::k_epsilon_launder_sharma, 120, 120, 80},
                                             PipeCase{FlowSolverParameters::Turbulence::k_omega_sst, 120, 120, 80}),
                           [](const auto &info) {
                             return test_name(info.param.model);
                           });
} // namespace servodrift::flow

namespace servodrift::flow
{
  // Launder-Sharma k-epsilon below transition: with a parabolic inlet at Re_D = 200 and 5 % inlet
  // intensity, the Launder-Sharma damping keeps the turbulent viscosity a few percent of mu and decaying, the run
  // converges (the k and epsilon residuals are measured against the inflow's level, not against the
  // vanishing local one, which would never let them fall), and the pressure drop is the laminar
  // run's within 1 % (mu_t/mu of a few percent near the inlet, 4 R long).
  TEST(FlowCore, KEpsilonStaysLaminarBelowTransition)
  {
    const double L = 4, R = 1, U = 1, mu = 0.01, rho = 1;
    const FvMesh mesh = rectangle(Geometry::axisymmetric, 0, L, 0, R, 128, 32);
    auto inlet = BoundaryCondition::velocity_inlet([&](const Vector2 &x) { return Vector2(2 * U * (1 - x.y() * x.y()), 0); });
    inlet.turbulence_length = 0.1 * R;
    const auto bc = pipe_boundaries(inlet);
    auto s = settings(1e-6);
    SimplecSolver laminar(mesh, {rho, mu}, bc, s);
    laminar.solve();
    s.turbulence = FlowSolverParameters::Turbulence::k_epsilon_launder_sharma;
    s.turbulence_relaxation = 0.5;
    SimplecSolver solver(mesh, {rho, mu}, bc, s);
    const SolveReport report = solver.solve();
    double upstream = 0, downstream = 0;
    for (std::size_t c = 0; c < mesh.n_cells(); ++c)
      {
        double &largest = mesh.cell_center[c].x() < 0.5 * L ? upstream : downstream;
        largest = std::max(largest, solver.turbulent_viscosity()[c] / mu);
      }
    auto drop = [](const SimplecSolver &x) { return x.mean_pressure("left") - x.mean_pressure("right"); };
    std::printf("k-epsilon at Re 200: dp/dp_laminar - 1 = %.3e, mu_t/mu up to %.2e upstream, %.2e downstream, %u iterations\n",
                drop(solver) / drop(laminar) - 1, upstream, downstream, report.iterations);
    EXPECT_CHECK_AT_MOST("Launder-Sharma, pipe Re_D 200: largest mu_t/mu upstream of mid-length", upstream, 0.1,
                         "laminar");
    EXPECT_CHECK_AT_MOST("Launder-Sharma, pipe Re_D 200: largest mu_t/mu, downstream half / upstream half",
                         downstream / upstream, 1, "falling downstream");
    EXPECT_CHECK_ABSOLUTE("Launder-Sharma, pipe Re_D 200: dp/dp_laminar - 1", drop(solver) / drop(laminar) - 1, 0, 1e-2,
                          "the laminar run");
  }
} // namespace servodrift::flow
