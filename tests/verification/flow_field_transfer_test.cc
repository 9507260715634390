// Verification of grid sequencing (flow/fv/field_transfer): the transfer between meshes is bounded and
// exact on the same mesh, and a fine mesh started from a coarse one's fields lands on the answer of
// the fine mesh from rest.
#include "common/error.h"
#include "flow/fv/field_transfer.h"
#include "flow/fv/fv_mesh.h"
#include "flow/fv/simplec.h"
#include "tests/support/checks.h"
#include "tests/support/test_support.h"
#include "tests/verification/flow_test_domains.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace servodrift::flow
{
  using namespace domains;

  // Grid sequencing (flow/fv/field_transfer): the transfer is a convex combination of the nearest
  // source cells, so the same mesh maps onto itself exactly, a constant stays that constant, the
  // carried values stay within the source's range (k, epsilon >= 0, the liquid fraction in [0, 1]),
  // and a linear field is carried with an error below one source cell's change of it.
  TEST(FlowCore, FieldTransferIsBoundedAndExactOnTheSameMesh)
  {
    const FvMesh coarse = rectangle(Geometry::axisymmetric, 0, 4, 0, 1, 20, 5, true);
    const FvMesh fine = rectangle(Geometry::axisymmetric, 0, 4, 0, 1, 80, 20);
    FlowFields f;
    f.density = 850;
    f.turbulent = true;
    f.boundary_pressures = {{"left", 2.0}};
    const std::size_t n = coarse.n_cells();
    f.u.resize(n), f.v.assign(n, 0.25), f.p.resize(n), f.k.resize(n), f.epsilon.resize(n), f.turbulent_viscosity.resize(n);
    f.liquid_fraction.resize(n), f.cavitating.resize(n);
    for (std::size_t c = 0; c < n; ++c)
      {
        const Vector2 &x = coarse.cell_center[c];
        f.u[c] = 3 * x.x() - 2 * x.y();        // linear
        f.p[c] = std::sin(5 * x.x()) * x.y(); // not
        f.k[c] = x.y() * x.y();
        f.epsilon[c] = x.x();
        f.turbulent_viscosity[c] = 1e-3;
        f.cavitating[c] = x.x() > 2;
        f.liquid_fraction[c] = f.cavitating[c] ? 0.5 * (x.x() - 2) / 2 : 1.0;
      }
    const FlowFields same = transfer_fields(coarse, f, coarse);
    EXPECT_EQ(same.u, f.u);
    EXPECT_EQ(same.p, f.p);
    EXPECT_EQ(same.liquid_fraction, f.liquid_fraction);
    EXPECT_TRUE(same.flux.empty());

    const FlowFields t = transfer_fields(coarse, f, fine);
    ASSERT_EQ(t.u.size(), fine.n_cells());
    EXPECT_EQ(t.face_area, fine.face_area);
    EXPECT_EQ(t.boundary_pressures, f.boundary_pressures);
    auto range = [](const std::vector<double> &x) { return std::minmax_element(x.begin(), x.end()); };
    // the coarse triangles' size: the square cell side 0.2 times sqrt 2 on the diagonal
    const double coarse_cell = 0.2 * std::sqrt(2.0), slope = std::hypot(3.0, 2.0);
    double worst_linear = 0;
    for (std::size_t c = 0; c < fine.n_cells(); ++c)
      {
        const Vector2 &x = fine.cell_center[c];
        worst_linear = std::max(worst_linear, std::abs(t.u[c] - (3 * x.x() - 2 * x.y())));
        EXPECT_DOUBLE_EQ(t.v[c], 0.25);
        EXPECT_DOUBLE_EQ(t.turbulent_viscosity[c], 1e-3);
        EXPECT_EQ(bool(t.cavitating[c]), t.liquid_fraction[c] < 1) << "cell " << c;
      }
    std::printf("field transfer: largest error of a linear field %.3f (slope x coarse cell %.3f)\n", worst_linear,
                slope * coarse_cell);
    EXPECT_CHECK_AT_MOST("field transfer, 20 x 5 triangles to 80 x 20 quadrilaterals: largest error of a linear field",
                         worst_linear, slope * coarse_cell, "its change over a source cell");
    for (const auto &[source, target] : {std::pair{&f.p, &t.p}, {&f.k, &t.k}, {&f.epsilon, &t.epsilon},
                                         {&f.liquid_fraction, &t.liquid_fraction}})
      {
        EXPECT_GE(*range(*target).first, *range(*source).first);
        EXPECT_LE(*range(*target).second, *range(*source).second);
      }
    EXPECT_THROW(transfer_fields(fine, f, coarse), std::invalid_argument);
  }

  // A start from fields carried from a coarser mesh (fluxes rebuilt from the face velocities by
  // set_fields) converges to the same answer as a start from rest, in fewer iterations: the
  // total-pressure-driven Hagen-Poiseuille pipe, 20 x 10 carried to 80 x 40.
  TEST(FlowCore, StartsFromFieldsOfACoarserMesh)
  {
    const double L = 4, R = 1, mu = 1, rho = 1e-3, dp = 8 * mu * 1 * L / (R * R);
    const std::map<std::string, BoundaryCondition> bc{{"left", BoundaryCondition::total_pressure_inlet(dp)},
                                                      {"right", BoundaryCondition::pressure_outlet(0)},
                                                      {"top", BoundaryCondition::wall()},
                                                      {"bottom", BoundaryCondition::axis()}};
    const FvMesh coarse_mesh = rectangle(Geometry::axisymmetric, 0, L, 0, R, 20, 10);
    const FvMesh fine_mesh = rectangle(Geometry::axisymmetric, 0, L, 0, R, 80, 40);
    SimplecSolver coarse(coarse_mesh, {rho, mu}, bc, settings());
    coarse.solve();
    SimplecSolver from_rest(fine_mesh, {rho, mu}, bc, settings());
    const unsigned int rest_iterations = from_rest.solve().iterations;
    SimplecSolver sequenced(fine_mesh, {rho, mu}, bc, settings());
    sequenced.set_fields(transfer_fields(coarse_mesh, coarse.fields(), fine_mesh));
    const unsigned int sequenced_iterations = sequenced.solve().iterations;
    const double Q_rest = from_rest.flow_rate("right"), Q_sequenced = sequenced.flow_rate("right");
    std::printf("grid sequencing: %u iterations from rest, %u from the coarse mesh's fields; Q differs by %.1e\n",
                rest_iterations, sequenced_iterations, Q_sequenced / Q_rest - 1);
    // both converged to 1e-8: the same discrete solution
    EXPECT_CHECK_ABSOLUTE("pipe 80 x 40 started from the 20 x 10 fields: Q/Q_from_rest - 1", Q_sequenced / Q_rest - 1,
                          0, 1e-6, "the start from rest");
    EXPECT_LT(sequenced_iterations, rest_iterations);
  }
} // namespace servodrift::flow
