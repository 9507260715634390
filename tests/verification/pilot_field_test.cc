// Field level of the pilot stage (flow/pilot_field, issue 5, laminar part): the axisymmetric fixed
// orifice and nozzle-flapper cases of RV-1 at 40 degC on their default meshes.
// - the meshes resolve what the issue asks: 30 cells across the bore radius, 20 across the gap;
// - fixed orifice, laminar, Re_0 = 110..490: C_d within 5 % of Lichtarowicz (E21, the issue's
//   tolerance; measured -1.3 .. -4.6 %, and within 0.4 % of a mesh 1.5 times finer);
// - nozzle-flapper: axial momentum is conserved between the bore's exit and the flapper (model.md
//   C12 (1), 2 %); C_dn at a laminar operating point within 10 % of E22; the flapper force falls as
//   the gap opens;
// - bad cases (closed gap, reversed pressure difference) are refused.
#include "common/error.h"
#include "common/units.h"
#include "flow/pilot_closed_forms.h"
#include "flow/pilot_field.h"
#include "tests/support/test_support.h"

#include <gtest/gtest.h>

#include <cmath>

namespace servodrift::flow
{
  namespace
  {
    ValveDescription laminar_valve()
    {
      ValveDescription v = test::valve();
      v.flow_solver.tolerance = 1e-6;
      return v;
    }

    /// Cells the segment from a to b crosses: those whose vertices lie on both sides of its line and
    /// whose centre lies between its ends.
    std::size_t cells_across(const FvMesh &mesh, const Vector2 &a, const Vector2 &b)
    {
      std::size_t count = 0;
      const Vector2 t = (b - a).normalized(), normal(-t.y(), t.x());
      const double length = (b - a).norm();
      for (std::size_t c = 0; c < mesh.n_cells(); ++c)
        {
          double lo = 1e300, hi = -1e300;
          for (unsigned int k = 0; k < mesh.cell_n_points[c]; ++k)
            {
              const double side = (mesh.points[mesh.cell_points[c][k]] - a).dot(normal);
              lo = std::min(lo, side), hi = std::max(hi, side);
            }
          const double along = (mesh.cell_center[c] - a).dot(t);
          if (lo <= 0 && hi > 0 && along > 0 && along < length)
            ++count;
        }
      return count;
    }
  } // namespace

  TEST(PilotField, MeshesResolveTheBoreAndTheGap)
  {
    const ValveDescription v = laminar_valve();
    const PilotFieldCase c = pilot_field_case(v, 40);
    const PilotField orifice(v, PilotGeometry::fixed_orifice, c);
    const double r0 = orifice.bore_radius(), l = 0.5e-3;
    const std::size_t across_bore = cells_across(orifice.mesh(), Vector2(0.5 * l, 0), Vector2(0.5 * l, r0));
    const PilotField nozzle(v, PilotGeometry::nozzle_flapper, c, 40e-6);
    const std::size_t across_gap = cells_across(nozzle.mesh(), Vector2(0, 0.27e-3), Vector2(40e-6, 0.27e-3));
    std::printf("orifice %zu cells, %zu across the bore radius; nozzle %zu cells, %zu across the gap\n",
                orifice.n_cells(), across_bore, nozzle.n_cells(), across_gap);
    EXPECT_GE(across_bore, 30u);
    EXPECT_GE(across_gap, 20u);
    for (unsigned int n : orifice.mesh().cell_n_points)
      ASSERT_EQ(n, 4u);
  }

  TEST(PilotField, FixedOrificeFollowsLichtarowiczInTheLaminarRange)
  {
    const ValveDescription v = laminar_valve();
    const PilotClosedForms closed_forms(v, 40);
    PilotField orifice(v, PilotGeometry::fixed_orifice, pilot_field_case(v, 40));
    for (double dp : {20e3, 100e3, 400e3}) // Re_0 = 110, 247, 493; continuation from one to the next
      {
        const PilotFieldResult r = orifice.solve(dp);
        const OrificeState e21 = closed_forms.fixed_orifice(dp);
        std::printf("fixed orifice dp %.3g Pa: Re_0 %.1f (E17 %.1f), C_d %.4f, Lichtarowicz %.4f (%+.2f %%), %u iterations\n",
                    dp, r.reynolds_number, e21.reynolds_number, r.discharge_coefficient, e21.discharge_coefficient,
                    100 * (r.discharge_coefficient / e21.discharge_coefficient - 1), r.iterations);
        EXPECT_NEAR(r.reynolds_number / e21.reynolds_number, 1, 1e-12); // the same definition, E17
        EXPECT_NEAR(r.discharge_coefficient / e21.discharge_coefficient, 1, 0.05);
        EXPECT_LT(orifice.solver().max_cell_imbalance(), 1e-8);
      }
  }

  TEST(PilotField, NozzleFlapperConservesMomentumAndFollowsTheGap)
  {
    const ValveDescription v = laminar_valve();
    const PilotClosedForms closed_forms(v, 40);
    const PilotFieldCase c = pilot_field_case(v, 40);
    const double A_N = units::pi * std::pow(closed_forms.geometry().nozzle_diameter, 2) / 4;
    const double dp = 0.1e6; // Re_n = 36: laminar
    std::vector<double> force;
    std::unique_ptr<PilotField> previous;
    for (double gap : {30e-6, 40e-6, 50e-6})
      {
        auto nozzle = std::make_unique<PilotField>(v, PilotGeometry::nozzle_flapper, c, gap);
        if (previous)
          nozzle->initialize_from(*previous); // continuation over the gap
        const PilotFieldResult r = nozzle->solve(dp);
        const OrificeState e = closed_forms.nozzle(gap, dp);
        // C12 (1): the flapper's force minus the land's equals the axial momentum through the bore's
        // exit, (p_bore - p_r) A_N + rho Q^2/A_N for a uniform exit velocity
        const double momentum = r.bore_pressure * A_N + c.fluid.density * r.flow_rate * r.flow_rate / A_N;
        std::printf("nozzle h %.0f um, dp %.3g Pa: Re_n %.1f, C_dn %.4f (E22 %.4f), F %.5f N (E23 %.5f), land %.5f N, "
                    "momentum balance %+.2f %%, p_min %.4g Pa, %u iterations\n",
                    gap * 1e6, dp, r.reynolds_number, r.discharge_coefficient, e.discharge_coefficient, r.flapper_force,
                    e.flapper_force, r.land_force, 100 * ((r.flapper_force - r.land_force) / momentum - 1),
                    r.minimum_pressure, r.iterations);
        EXPECT_NEAR((r.flapper_force - r.land_force) / momentum, 1, 0.02);
        if (gap == 40e-6)
          {
            EXPECT_NEAR(r.discharge_coefficient / e.discharge_coefficient, 1, 0.10);
          }
        force.push_back(r.flapper_force);
        previous = std::move(nozzle);
      }
    EXPECT_GT(force[0], force[1]);
    EXPECT_GT(force[1], force[2]);
  }

  TEST(PilotField, RefusesClosedGapsAndReversedPressures)
  {
    const ValveDescription v = laminar_valve();
    const PilotFieldCase c = pilot_field_case(v, 40);
    EXPECT_THROW(PilotField(v, PilotGeometry::nozzle_flapper, c, 0.0), InputError);
    PilotField orifice(v, PilotGeometry::fixed_orifice, c);
    EXPECT_THROW(orifice.solve(-1e5), InputError);
    EXPECT_THROW(orifice.solve(0), InputError);
  }
} // namespace servodrift::flow
