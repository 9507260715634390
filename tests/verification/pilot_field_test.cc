// Field level of the pilot stage (flow/pilot/pilot_field, issue 5): the axisymmetric fixed orifice and
// nozzle-flapper cases of RV-1 at 40 degC on their default meshes, as physics (their numerics:
// pilot_field_numerics_test.cc; the stage's sweep: pilot_field_stage_test.cc).
// - the meshes resolve what the issue asks: 30 cells across the bore radius, 20 across the gap;
// - fixed orifice against Lichtarowicz (E21) within 5 %: laminar at Re_0 = 110..490 (measured
//   -1.3 .. -4.6 %), two-layer k-epsilon at Re_0 = 2000 and 5000 (-2.8, -3.5 %);
// - nozzle-flapper: axial momentum conserved between the bore's exit and the flapper (C12 (1));
//   C_dn within 10 % of E22; the force's trend in the gap, at fixed dp and in the orifice bridge;
// - mesh convergence (resolution 0.7, 1, 1.4: below 1 % between the two finest) and insensitivity
//   to the outlet radius and the plenum size (below 0.5 %);
// - laminar cavitating nozzle cases follow the quasi-static branch whatever their start; the
//   cavitating null; the mixture's mass balance in the liquid cells;
// - bad cases are refused (closed gap, reversed pressure difference).
#include "common/error.h"
#include "common/units.h"
#include "common/pilot_closed_forms.h"
#include "flow/pilot/pilot_field.h"
#include "tests/support/checks.h"
#include "tests/support/test_support.h"
#include "tests/verification/pilot_field_test_cases.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace servodrift::flow
{
  using test_cases::nozzle_at_null;
  using test_cases::orifice_laminar;

  namespace
  {
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
    const ValveDescription v = test::valve();
    const PilotFieldCase c = pilot_field_case(v, 40);
    const PilotField orifice(pilot_field_settings(v), PilotGeometry::fixed_orifice, c);
    const double r0 = orifice.bore_radius(), l = 0.5e-3;
    const std::size_t across_bore = cells_across(orifice.mesh(), Vector2(0.5 * l, 0), Vector2(0.5 * l, r0));
    const PilotField nozzle(pilot_field_settings(v), PilotGeometry::nozzle_flapper, c, 40e-6);
    const std::size_t across_gap = cells_across(nozzle.mesh(), Vector2(0, 0.27e-3), Vector2(40e-6, 0.27e-3));
    std::printf("orifice %zu cells, %zu across the bore radius; nozzle %zu cells, %zu across the gap\n",
                orifice.n_cells(), across_bore, nozzle.n_cells(), across_gap);
    EXPECT_CHECK_AT_LEAST("cells across the bore radius", double(across_bore), 30, "issue 5");
    EXPECT_CHECK_AT_LEAST("cells across the gap at 40 um", double(across_gap), 20, "issue 5");
    for (unsigned int n : orifice.mesh().cell_n_points)
      ASSERT_EQ(n, 4u);
  }

  TEST(PilotField, FixedOrificeFollowsLichtarowiczInTheLaminarRange)
  {
    const ValveDescription v = test::valve();
    const PilotClosedForms closed_forms(v, 40);
    PilotField orifice(pilot_field_settings(v), PilotGeometry::fixed_orifice, pilot_field_case(v, 40));
    // continuation from one to the next
    for (const auto &[dp, reynolds] : {std::pair{20e3, "110"}, std::pair{100e3, "247"}, std::pair{400e3, "493"}})
      {
        const PilotFieldResult r = orifice.solve(dp);
        const OrificeState e21 = closed_forms.fixed_orifice(dp);
        std::printf("fixed orifice dp %.3g Pa: Re_0 %.1f (E17 %.1f), C_d %.4f, Lichtarowicz %.4f (%+.2f %%), %u iterations\n",
                    dp, r.reynolds_number, e21.reynolds_number, r.discharge_coefficient, e21.discharge_coefficient,
                    100 * (r.discharge_coefficient / e21.discharge_coefficient - 1), r.iterations);
        EXPECT_NEAR(r.reynolds_number / e21.reynolds_number, 1, 1e-12); // the same definition, E17
        EXPECT_CHECK_RELATIVE(std::string("fixed orifice C_d, laminar, Re_0 ") + reynolds, r.discharge_coefficient,
                              e21.discharge_coefficient, 0.05, "Lichtarowicz E21");
        EXPECT_LT(orifice.solver().max_cell_imbalance(), 1e-8);
      }
  }

  TEST(PilotField, NozzleFlapperConservesMomentumAndFollowsTheGap)
  {
    const ValveDescription v = test::valve();
    const PilotClosedForms closed_forms(v, 40);
    const PilotFieldCase c = pilot_field_case(v, 40);
    const double A_N = units::pi * std::pow(closed_forms.geometry().nozzle_diameter, 2) / 4;
    const double dp = 0.1e6; // Re_n = 36: laminar
    std::vector<double> force;
    std::unique_ptr<PilotField> previous;
    for (double gap : {30e-6, 40e-6, 50e-6})
      {
        auto nozzle = std::make_unique<PilotField>(pilot_field_settings(v), PilotGeometry::nozzle_flapper, c, gap);
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

  TEST(PilotField, ColdOrificeFollowsTheCreepingFlowThroughAPore)
  {
    // At -55 degC the fixed orifice's flow is creeping at low pressure differences. Its limit for
    // Re -> 0 is Sampson's flow through a hole plus the bore's Poiseuille flow (Dagan, Weinbaum and
    // Pfeffer 1982), C_d = Re/(4 pi (3 + 16 l/(pi D))), which E21's laminar term (Lichtarowicz,
    // fitted above Re 10) overestimates by 40 %. The superposition is itself approximate: numerical
    // creeping flows through short pores (L/D 0.1, 0.37) have 5-6 % less resistance. Checked at Re_0
    // about 0.2 and 4: within 6 % of the creeping limit, and the same within 0.5 % at both (inertia
    // does not yet count at Re 4: flow/pilot/pilot_field_cases.h's creeping Reynolds number).
    const ValveDescription v = test::valve();
    const double T = -55;
    const PilotClosedForms closed_forms(v, T);
    PilotField orifice(pilot_field_settings(v), PilotGeometry::fixed_orifice, pilot_field_case(v, T));
    std::vector<double> ratio;
    for (const auto &[dp, reynolds] : {std::pair{2.5e3, "0.2"}, std::pair{1.03e6, "4"}})
      {
        const PilotFieldResult r = orifice.solve(dp);
        const double creeping = closed_forms.creeping_fixed_orifice(dp).discharge_coefficient;
        ratio.push_back(r.discharge_coefficient / creeping);
        std::printf("cold orifice dp %.3g Pa: Re_0 %.3g, C_d %.5f, creeping limit %.5f (ratio %.4f), E21 %.5f\n", dp,
                    r.reynolds_number, r.discharge_coefficient, creeping, ratio.back(),
                    closed_forms.fixed_orifice(dp).discharge_coefficient);
        EXPECT_CHECK_RELATIVE(std::string("fixed orifice C_d at -55 degC, Re_0 ") + reynolds, r.discharge_coefficient,
                              creeping, 0.06, "Sampson + Poiseuille");
      }
    RecordProperty("creeping_orifice_ratio_low_re", test::number(ratio[0]));
    RecordProperty("creeping_orifice_ratio_re_4", test::number(ratio[1]));
    EXPECT_CHECK_RELATIVE("C_d / creeping limit, Re_0 4 against 0.2", ratio[1], ratio[0], 0.005, "Re_0 0.2");
  }

  TEST(PilotField, ColdNozzleTendsToTheLubricationLimit)
  {
    // At -55 degC (nu about 2500 mm^2/s, Re_n below 0.1) the nozzle's flow is creeping (issue 65).
    // The lubrication limit, the bore's Poiseuille resistance in series with the radial flow over
    // the land (PilotClosedForms::creeping_nozzle), leaves out the end effects at the land's
    // edges, which add resistance over a length of order h: the field's Q/Q_lub = 1 - c h/r_N.
    // Checked: below 1 at h = 10 and 20 um, further below at 20, and extrapolated to h = 0 (2 r(10)
    // - r(20)) within 1 % of 1; and Q proportional to dp (Stokes flow) within 0.1 % from 3.09 to
    // 12.36 MPa.
    const ValveDescription v = test::valve();
    const double T = -55, dp = 3.09e6;
    const PilotClosedForms closed_forms(v, T);
    const PilotFieldCase c = pilot_field_case(v, T);
    const double bore_length = nozzle_bore_length_in_radii * closed_forms.geometry().nozzle_diameter / 2;
    std::vector<double> ratio;
    std::unique_ptr<PilotField> previous;
    for (double gap : {10e-6, 20e-6})
      {
        auto nozzle = std::make_unique<PilotField>(pilot_field_settings(v), PilotGeometry::nozzle_flapper, c, gap);
        if (previous)
          nozzle->initialize_from(*previous);
        const PilotFieldResult r = nozzle->solve(dp);
        const double lubrication = closed_forms.creeping_nozzle(gap, dp, bore_length).flow_rate;
        ratio.push_back(r.flow_rate / lubrication);
        std::printf("cold nozzle h %.0f um, dp %.3g Pa: Re_n %.3g, Q %.5g m^3/s, lubrication limit %.5g (ratio %.4f), "
                    "E22 %.5g, %u iterations\n",
                    gap * 1e6, dp, r.reynolds_number, r.flow_rate, lubrication, ratio.back(),
                    closed_forms.nozzle(gap, dp).flow_rate, r.iterations);
        EXPECT_LT(r.reynolds_number, 0.1);
        if (gap == 20e-6)
          {
            const PilotFieldResult higher = nozzle->solve(4 * dp);
            EXPECT_CHECK_RELATIVE("Q(4 dp) / 4 Q(dp), 20 um, 3.09 MPa", higher.flow_rate / (4 * r.flow_rate), 1, 1e-3,
                                  "Stokes flow");
          }
        previous = std::move(nozzle);
      }
    const double limit = 2 * ratio[0] - ratio[1];
    RecordProperty("lubrication_ratio_10um", test::number(ratio[0]));
    RecordProperty("lubrication_ratio_20um", test::number(ratio[1]));
    RecordProperty("lubrication_ratio_extrapolated", test::number(limit));
    EXPECT_CHECK_AT_MOST("Q/Q_lub at 10 um", ratio[0], 1, "lubrication limit");
    EXPECT_CHECK_AT_MOST("Q/Q_lub at 20 um", ratio[1], ratio[0], "Q/Q_lub at 10 um");
    EXPECT_CHECK_ABSOLUTE("Q/Q_lub extrapolated to h = 0", limit, 1, 0.01, "lubrication limit");
  }

  TEST(PilotField, RefusesClosedGapsAndReversedPressures)
  {
    const ValveDescription v = test::valve();
    const PilotFieldCase c = pilot_field_case(v, 40);
    EXPECT_THROW(PilotField(pilot_field_settings(v), PilotGeometry::nozzle_flapper, c, 0.0), InputError);
    PilotField orifice(pilot_field_settings(v), PilotGeometry::fixed_orifice, c);
    EXPECT_THROW(orifice.solve(-1e5), InputError);
    EXPECT_THROW(orifice.solve(0), InputError);
  }
  // Laminar cavitating nozzle cases have more than one steady solution: RV-1's null gap at 120 degC
  // and 3.09 MPa (the sweep's lowest nozzle pressure) carried from its start-up (Re 300, 0.1 MPa) in
  // one step converges to C_dn 0.6043, with a cavity that chokes part of the curtain; carried in
  // steps of 3 or of 2 to 0.6398, both (measured, the quasi-static branch; at 110 degC one step
  // diverged, steps of 3, of 2 and eight steps of 1.2-2 gave 0.6439 and a step of 5.8 0.6097).
  // `Field solution/Continuation ratio' (3) puts every case on the quasi-static path: from rest with the
  // default ratio, C_dn must agree with a path of ratio 1.5 within 1 %: the residual hysteresis of the
  // cavity measured elsewhere (30 um gap, paths of ratio 2 and 3: 0.5 %), far below the 5.6 % gap
  // between the branches. The one-step path is printed, not asserted: which branch a jump lands
  // on depends on rounding (a gap 1 ulp smaller took the 110 degC jump to the quasi-static branch).
  TEST(PilotField, LaminarCavitatingNozzleFollowsTheQuasiStaticBranch)
  {
    const ValveDescription v = test::valve();
    PilotFieldCase c = pilot_field_case(v, 120);
    c.turbulence = FlowSolverParameters::Turbulence::laminar;
    const double gap = v.pilot.null_gap, dp = 0.15 * (v.operating.supply_pressure - v.operating.return_pressure);
    auto from_rest = [&](double ratio) {
      PilotField nozzle(pilot_field_settings(v), PilotGeometry::nozzle_flapper, c, gap);
      if (ratio > 0)
        nozzle.set_continuation_ratio(ratio);
      return nozzle.solve(dp);
    };
    const PilotFieldResult path = from_rest(0), fine = from_rest(1.5);
    double jump = std::nan("");
    try
      {
        jump = from_rest(1e6).discharge_coefficient;
      }
    catch (const std::runtime_error &) // a jump may also diverge
      {
      }
    std::printf("nozzle 120 degC, h %.0f um, dp %.3g MPa, laminar: C_dn %.5f (default path, %u iterations), %.5f (steps "
                "of 1.5, %u iterations), %.5f (one step from the start-up)\n",
                gap * 1e6, dp * 1e-6, path.discharge_coefficient, path.iterations, fine.discharge_coefficient,
                fine.iterations, jump);
    ASSERT_TRUE(path.cavitating);
    EXPECT_NEAR(path.discharge_coefficient / fine.discharge_coefficient, 1, 0.01);
    EXPECT_NEAR(path.flapper_force / fine.flapper_force, 1, 0.01);
  }

  // RV-1's nozzle at its null conditions with cavitation (40 degC, dp = 10.4 MPa), x_f = -10, 0, +10 um:
  // - C12 (1), momentum conservation: flapper force minus land force equals the axial momentum
  //   through the bore's exit plane, int (p - p_r + rho u_x^2) dA, within 1 % (measured 0.4 %). Its
  //   uniform-velocity form (p_bore - p_r) A_N + rho Q^2/A_N is short by the momentum-flux factor
  //   beta of the exit profile (printed; 1.0 for a flat profile, 1.33 for Poiseuille);
  // - C_dn within 10 % of E22 at x0 (measured +2.5 %);
  // - at a fixed dp the force grows with the gap, as in E23 (the curtain momentum grows with h);
  //   in the valve, where the fixed orifice feeds the nozzle, the control pressure falls as the gap
  //   opens and the force with it: F(h) (p_c(h) - p_r)/dp with p_c from the orifice-nozzle bridge
  //   (E21 for the orifice, the field's C_dn) falls with h, and its change is odd in x_f to first
  //   order: the even part F(x0-x) + F(x0+x) - 2 F(x0) is below a quarter of the odd part;
  // - E23 is reported beside (C12 (2)): the suction ring at the land makes the field force lower.
  TEST(PilotField, NozzleAtTheNullWithCavitation)
  {
    const ValveDescription v = test::valve();
    const PilotClosedForms closed_forms(v, 40);
    const PilotFieldCase c = pilot_field_case(v, 40);
    const auto &g = closed_forms.geometry();
    const double A_N = units::pi * std::pow(g.nozzle_diameter, 2) / 4, dp = 10.4e6;
    const double span = v.operating.supply_pressure - v.operating.return_pressure;
    const double orifice_conductance =
      closed_forms.fixed_orifice(span / 2).discharge_coefficient * units::pi * std::pow(g.fixed_orifice_diameter, 2) / 4;
    std::vector<double> force, bridge_force, e23, discharge, e22;
    double momentum_error = 0, smallest_beta = 1e300;
    std::unique_ptr<PilotField> previous;
    for (double gap : {40e-6, 30e-6, 50e-6})
      {
        auto nozzle = std::make_unique<PilotField>(pilot_field_settings(v), PilotGeometry::nozzle_flapper, c, gap);
        if (previous)
          nozzle->initialize_from(*previous);
        const PilotFieldResult r = nozzle->solve(dp);
        const OrificeState e = closed_forms.nozzle(gap, dp);
        const double uniform = r.bore_pressure * A_N + c.fluid.density * r.flow_rate * r.flow_rate / A_N;
        const double beta = (r.jet_force - r.bore_pressure * A_N) / (c.fluid.density * r.flow_rate * r.flow_rate / A_N);
        // the bridge: C_d0 A_0 sqrt(p_s - p_c) = C_dn pi D_N h sqrt(p_c - p_r)
        const double ratio = r.discharge_coefficient * units::pi * g.nozzle_diameter * gap / orifice_conductance;
        const double control = span / (1 + ratio * ratio);
        std::printf("nozzle h %.0f um, dp %.3g Pa: Re_n %.0f, C_dn %.4f (E22 %.4f, %+.1f %%), F %.4f N (E23 %.4f, %+.1f %%), "
                    "land %.4f N, momentum balance %+.2f %% (uniform-velocity form %+.2f %%, beta %.3f), "
                    "bridge p_c - p_r %.3f MPa, cavitating %d, %u iterations\n",
                    gap * 1e6, dp, r.reynolds_number, r.discharge_coefficient, e.discharge_coefficient,
                    100 * (r.discharge_coefficient / e.discharge_coefficient - 1), r.flapper_force, e.flapper_force,
                    100 * (r.flapper_force / e.flapper_force - 1), r.land_force,
                    100 * ((r.flapper_force - r.land_force) / r.jet_force - 1),
                    100 * ((r.flapper_force - r.land_force) / uniform - 1), beta, control * 1e-6, int(r.cavitating),
                    r.iterations);
        // the worst over the gaps (a NaN sticks)
        const double error = std::abs((r.flapper_force - r.land_force) / r.jet_force - 1);
        if (!(error <= momentum_error) && !std::isnan(momentum_error))
          momentum_error = error;
        if (!(beta >= smallest_beta) && !std::isnan(smallest_beta))
          smallest_beta = beta;
        if (gap == 40e-6)
          {
            EXPECT_CHECK_RELATIVE("nozzle C_dn at the null (40 um, 10.4 MPa)", r.discharge_coefficient,
                                  e.discharge_coefficient, 0.10, "E22");
            previous = std::move(nozzle);
          }
        force.push_back(r.flapper_force);
        e23.push_back(e.flapper_force);
        discharge.push_back(r.discharge_coefficient);
        e22.push_back(e.discharge_coefficient);
        bridge_force.push_back(r.flapper_force * control / dp);
      }
    // the gaps in the order 30, 40, 50 um
    const auto in_gap_order = [](const std::vector<double> &x) {
      return test::shown(x[1]) + ", " + test::shown(x[0]) + ", " + test::shown(x[2]);
    };
    EXPECT_CHECK_AT_MOST("flapper minus land force against the exit's axial momentum, 30-50 um (relative)",
                         momentum_error, 0.01, "C12 (1)");
    EXPECT_CHECK_AT_LEAST("momentum-flux factor beta of the exit profile, 30-50 um", smallest_beta, 1.0,
                          "a flat profile");
    test::record_check("nozzle C_dn at 30, 50 um, 10.4 MPa", "E22: " + test::shown(e22[1]) + ", " + test::shown(e22[2]),
                       "- (reported)", test::shown(discharge[1]) + ", " + test::shown(discharge[2]));
    // at fixed dp: the sign of E23's trend
    EXPECT_LT(force[1], force[0]);
    EXPECT_LT(force[0], force[2]);
    EXPECT_LT(e23[1], e23[0]);
    test::record_check("flapper force at 30, 40, 50 um, 10.4 MPa [N]",
                       "grows with h as E23's (E23: " + in_gap_order(e23) + ", C12 (2))", "strict",
                       in_gap_order(force));
    // in the bridge: falls as the gap opens, odd to first order
    const double F0 = bridge_force[0], F_closing = bridge_force[1], F_opening = bridge_force[2];
    EXPECT_GT(F_closing, F0);
    EXPECT_GT(F0, F_opening);
    const double odd = F_closing - F_opening, even = F_closing + F_opening - 2 * F0;
    std::printf("bridge force change: odd part %.4f N (K_f %.0f N/m), even part %.4f N (ratio %.3f)\n", odd,
                odd / 20e-6, even, even / odd);
    test::record_check("force in the orifice-nozzle bridge, 30, 40, 50 um [N]", "falls as the gap opens", "strict",
                       in_gap_order(bridge_force) + " (K_f " + test::shown(odd / 20e-6 * 1e-3) + " kN/m)");
    EXPECT_CHECK_AT_MOST("bridge force change: |even part / odd part|", std::abs(even / odd), 0.25,
                         "odd in x_f to first order");
  }

  // The mass balance with cavitation (issue 27): the pressure correction balances the mixture's mass
  // (each face's flux times its upwind mixture density ratio) of every liquid cell to round-off, and
  // SimplecSolver::max_cell_imbalance reports that mixture balance; the flux at the liquid's density
  // does not balance where the vapour expands, so it is not the mass balance. In the cavitating
  // cells the liquid fraction carries the balance, and the convergence test does not see it: at this
  // case (RV-1's null gap, full pressure, resolution 0.5) they hold 2.6e-3 of the throughput and the
  // outflow is 0.25 % below the inflow (doc/validation.md, known limits).
  TEST(PilotField, CavitatingCaseBalancesTheMixturesMassInItsLiquidCells)
  {
    const ValveDescription v = test::valve();
    PilotFieldCase c = pilot_field_case(v, 40);
    c.resolution = 0.5;
    PilotField nozzle(pilot_field_settings(v), PilotGeometry::nozzle_flapper, c, 40e-6);
    const PilotFieldResult r = nozzle.solve(20.6e6);
    ASSERT_TRUE(r.cavitating);
    const SimplecSolver &solver = nozzle.solver();
    const FvMesh &mesh = nozzle.mesh();
    const FlowFields fields = solver.fields(); // fluxes F at the liquid's density, the cavitating cells
    auto net = [&](const std::vector<double> &flux) {
      std::vector<double> sum(mesh.n_cells(), 0.0);
      for (std::size_t f = 0; f < mesh.n_faces(); ++f)
        {
          sum[mesh.owner[f]] += flux[f];
          if (mesh.neighbour[f] >= 0)
            sum[mesh.neighbour[f]] -= flux[f];
        }
      for (double &x : sum)
        x = std::abs(x) / solver.throughput();
      return sum;
    };
    const std::vector<double> mixture = net(solver.mass_flux()), liquid_density = net(fields.flux);
    double liquid_cells = 0, cavitating_cells = 0, cavitating_liquid_density = 0;
    for (std::size_t cell = 0; cell < mesh.n_cells(); ++cell)
      if (fields.cavitating[cell])
        cavitating_cells = std::max(cavitating_cells, mixture[cell]),
        cavitating_liquid_density = std::max(cavitating_liquid_density, liquid_density[cell]);
      else
        liquid_cells = std::max(liquid_cells, mixture[cell]);
    std::printf("%td cavitating cells; largest mixture imbalance: liquid cells %.2e, cavitating cells %.2e "
                "(at the liquid's density %.2e); net %.2e (of the throughput)\n",
                std::count(fields.cavitating.begin(), fields.cavitating.end(), 1), liquid_cells, cavitating_cells,
                cavitating_liquid_density, solver.net_imbalance());
    EXPECT_CHECK_AT_MOST("largest mixture imbalance of a liquid cell (of the throughput)", liquid_cells, 1e-9,
                         "round-off");
    test::record_check("largest mixture imbalance of a cavitating cell (of the throughput)",
                       "not in the convergence test (a known limit)", "- (reported)", test::shown(cavitating_cells));
    EXPECT_DOUBLE_EQ(solver.max_cell_imbalance(), std::max(liquid_cells, cavitating_cells));
    EXPECT_GT(cavitating_liquid_density, 5 * cavitating_cells);
  }

  // Mesh convergence at the cases' conditions: resolution 0.7, 1 and 1.4 (cell counts 1 : 2 : 4);
  // between the two finest C_d and force change by less than 1 % (the tolerance).
  SLOW_TEST(PilotField, MeshConvergence)
  {
    ValveDescription v = test::valve();
    v.flow_solver.max_iterations = 15000; // SIMPLEC's rate falls with the cell count: the finest needs about 7000
    std::vector<PilotFieldResult> nozzle, orifice;
    for (double resolution : {0.7, 1.0, 1.4})
      {
        nozzle.push_back(nozzle_at_null(v, 40e-6, resolution));
        orifice.push_back(orifice_laminar(v, resolution));
        std::printf("resolution %.1f: nozzle C_dn %.5f, F %.5f N; orifice C_d %.5f\n", resolution,
                    nozzle.back().discharge_coefficient, nozzle.back().flapper_force, orifice.back().discharge_coefficient);
      }
    EXPECT_CHECK_RELATIVE("nozzle C_dn at the null, resolution 1", nozzle[1].discharge_coefficient,
                          nozzle[2].discharge_coefficient, 0.01, "resolution 1.4");
    EXPECT_CHECK_RELATIVE("flapper force at the null, resolution 1 [N]", nozzle[1].flapper_force,
                          nozzle[2].flapper_force, 0.01, "resolution 1.4");
    EXPECT_CHECK_RELATIVE("orifice C_d, laminar, Re_0 493, resolution 1", orifice[1].discharge_coefficient,
                          orifice[2].discharge_coefficient, 0.01, "resolution 1.4");
  }


  // The artificial boundaries do not matter: the nozzle's outlet radius 4 -> 6 land radii and the
  // orifice's plenum 6 -> 9 bore radii change C_d and force by less than 0.5 % (the tolerance).
  TEST(PilotField, InsensitiveToOutletRadiusAndPlenumSize)
  {
    ValveDescription v = test::valve();
    const PilotFieldResult nozzle = nozzle_at_null(v, 40e-6), orifice = orifice_laminar(v);
    v.pilot.field_mesh.outlet_radius *= 1.5;
    v.pilot.field_mesh.plenum_size *= 1.5;
    const PilotFieldResult nozzle_wide = nozzle_at_null(v, 40e-6), orifice_wide = orifice_laminar(v);
    std::printf("outlet radius x1.5: C_dn %+.3f %%, F %+.3f %%; plenum x1.5: C_d %+.3f %%\n",
                100 * (nozzle_wide.discharge_coefficient / nozzle.discharge_coefficient - 1),
                100 * (nozzle_wide.flapper_force / nozzle.flapper_force - 1),
                100 * (orifice_wide.discharge_coefficient / orifice.discharge_coefficient - 1));
    EXPECT_CHECK_RELATIVE("nozzle C_dn at the null, outlet radius 6 land radii", nozzle_wide.discharge_coefficient,
                          nozzle.discharge_coefficient, 0.005, "4 land radii");
    EXPECT_CHECK_RELATIVE("flapper force at the null, outlet radius 6 land radii [N]", nozzle_wide.flapper_force,
                          nozzle.flapper_force, 0.005, "4 land radii");
    EXPECT_CHECK_RELATIVE("orifice C_d, laminar, Re_0 493, plenum 9 bore radii", orifice_wide.discharge_coefficient,
                          orifice.discharge_coefficient, 0.005, "6 bore radii");
  }





} // namespace servodrift::flow
