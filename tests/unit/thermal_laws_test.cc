// The temperature-dependent laws against the numbers printed in model.md. model.md gives 3-4
// significant digits; each tolerance below is the rounding of the printed value.
#include "common/error.h"
#include "common/thermal_laws.h"
#include "tests/support/checks.h"
#include "tests/support/core_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

using namespace servodrift;
using test::relative;

TEST(OilLaw, VogelViscosityMatchesModelTable)
{
  // E16: 500 (-40), 46.6 (0), 23.5 (20), 14.0 (40), 9.36 (60), 6.78 (80), 5.20 (100), 4.17 (120) mm^2/s
  const auto v = test::rv1();
  const laws::Oil oil(v.fluid, 40);
  const std::pair<double, double> expected[] = {{-40, 500},  {0, 46.6},  {20, 23.5},  {40, 14.0},
                                                {60, 9.36}, {80, 6.78}, {100, 5.20}, {120, 4.17}};
  for (const auto &[T, nu] : expected)
    // printed to 3 significant digits: half a unit of the last digit is <= 0.5 % of 9.36
    EXPECT_CHECK_RELATIVE("Vogel viscosity E16 at " + format_number(T) + " degC [mm^2/s]",
                          oil.kinematic_viscosity(T).value * 1e6, nu, 0.006, "model.md E16");
}

TEST(OilLaw, VogelViscosityMeetsTheOilSpecificationOverTheWholeRange)
{
  // The limits of MIL-PRF-5606H for its class of oil (model.md 2.8): at least 13.2 mm^2/s at 40
  // degC and 4.90 at 100 degC, at most 600 at -40 and 2500 at -54. RV-1's Vogel law gives 14.0,
  // 5.20, 500 and 2212: inside each, and at -55 degC (2522) within 1 % of the -54 ceiling.
  const laws::Oil oil(test::rv1().fluid, 40);
  const auto nu = [&](double T) { return oil.kinematic_viscosity(T).value * 1e6; };
  EXPECT_CHECK_AT_LEAST("viscosity at 40 degC [mm^2/s]", nu(40), 13.2, "MIL-PRF-5606H");
  EXPECT_CHECK_AT_LEAST("viscosity at 100 degC [mm^2/s]", nu(100), 4.90, "MIL-PRF-5606H");
  EXPECT_CHECK_AT_MOST("viscosity at -40 degC [mm^2/s]", nu(-40), 600, "MIL-PRF-5606H");
  EXPECT_CHECK_AT_MOST("viscosity at -54 degC [mm^2/s]", nu(-54), 2500, "MIL-PRF-5606H");
  EXPECT_CHECK_AT_MOST("viscosity at -55 degC [mm^2/s]", nu(-55), 1.01 * 2500, "1 % above the -54 degC ceiling");
  // and falls monotonically to the top of the window, where it stays positive and finite
  bool falling = true;
  for (double T = -55; T < 150; T += 1)
    falling = falling && nu(T) > nu(T + 1);
  EXPECT_TRUE(falling);
  test::record_check("viscosity falls monotonically, -55 to 150 degC", "every 1 K", "strict", falling ? "yes" : "no");
}

TEST(OilLaw, LawRangesNameTheLawsATableLeaves)
{
  // The default range, -55 to 135 degC, and the paper's, 40-120, lie within every law's range: no
  // warning. A table from -58 degC leaves the oil density's (-55) but not the metals' (-60); one to
  // 160 degC leaves them all (the viscosity's window, `Fluid/Maximum temperature', also refuses
  // it). The sentence names the entry, the span and each law with its basis.
  const auto ranges = laws::law_ranges(test::rv1().fluid);
  EXPECT_EQ(laws::beyond_law_ranges(ranges, {-55, 0, 135}, "Sweeps/Table temperatures"), "");
  EXPECT_EQ(laws::beyond_law_ranges(ranges, {40, 120}, "Sweeps/Table temperatures"), "");
  const std::string cold = laws::beyond_law_ranges(ranges, {-58, 40}, "Sweeps/Table temperatures");
  EXPECT_NE(cold.find("`Sweeps/Table temperatures' reach -58 to 40 degC"), std::string::npos) << cold;
  EXPECT_NE(cold.find("oil density (E15) and effective bulk modulus (2.8) (-55 to 150 degC"), std::string::npos)
    << cold;
  EXPECT_EQ(cold.find("spring-tube modulus"), std::string::npos) << cold;
  const std::string hot = laws::beyond_law_ranges(ranges, {40, 160}, "x");
  for (const char *law : {"Vogel", "density", "remanence", "spring-tube modulus", "thermal expansion"})
    EXPECT_NE(hot.find(law), std::string::npos) << law << ": " << hot;
  // every law's range is stated in doc/method.md, as the code has it
  std::ifstream method(std::string(SERVODRIFT_SOURCE_DIR) + "/doc/method.md");
  const std::string doc((std::istreambuf_iterator<char>(method)), std::istreambuf_iterator<char>());
  for (const auto &r : ranges)
    EXPECT_NE(doc.find("| " + r.law + " | " + format_number(r.lowest) + " to " + format_number(r.highest) + " |"),
              std::string::npos)
      << r.law;
}

TEST(OilLaw, ViscosityDerivativeIsConsistent)
{
  const auto v = test::rv1();
  for (const char *law : {"vogel", "paper-exponential"})
    {
      auto p = v.fluid;
      p.viscosity_law = std::string(law) == "vogel" ? FluidParameters::ViscosityLaw::vogel :
                                                      FluidParameters::ViscosityLaw::paper_exponential;
      const laws::Oil oil(p, 40);
      const double h = 1e-3, numeric = (oil.kinematic_viscosity(80 + h).value - oil.kinematic_viscosity(80 - h).value) / (2 * h);
      // an O(h^2) central difference
      EXPECT_CHECK_RELATIVE(std::string("viscosity derivative at 80 degC, ") + law + " [m^2/(s K)]",
                            oil.kinematic_viscosity(80).slope, numeric, 1e-6, "central difference");
    }
}

TEST(OilLaw, PaperExponentialRatio)
{
  // E14: nu(120)/nu(40) = exp(-0.0626 * 80) = 6.68e-3 (model.md 1.7: 6.7e-3)
  auto f = test::rv1().fluid;
  f.viscosity_law = FluidParameters::ViscosityLaw::paper_exponential;
  const laws::Oil oil(f, 40);
  EXPECT_NEAR(oil.kinematic_viscosity(40).value, 14.0e-6, 1e-15);
  EXPECT_CHECK_ABSOLUTE("paper exponential E14: nu(120)/nu(40)",
                        oil.kinematic_viscosity(120).value / oil.kinematic_viscosity(40).value,
                        std::exp(-0.0626 * 80), 1e-15, "exp(-0.0626 * 80)");
}

TEST(OilLaw, DensityBulkModulusAndDynamicViscosity)
{
  const laws::Oil oil(test::rv1().fluid, 40);
  EXPECT_DOUBLE_EQ(oil.density(40).value, 850.0);
  EXPECT_CHECK_RELATIVE("density E15 at 120 degC [kg/m^3]", oil.density(120).value, 811.0, 0.001, "model.md 2.8");
  EXPECT_DOUBLE_EQ(oil.effective_bulk_modulus(40), 0.7e9);
  EXPECT_CHECK_RELATIVE("effective bulk modulus at 120 degC [Pa]", oil.effective_bulk_modulus(120),
                        0.7e9 * (1 - 0.004 * 80), 1e-14, "model.md 2.8: 0.7 GPa (1 - 0.004 dT)");
  // 1.7: mu = 0.0119 Pa*s at 40 degC, 0.0034 at 120 degC (printed to 3 and 2 digits)
  EXPECT_CHECK_RELATIVE("dynamic viscosity at 40 degC [Pa s]", oil.dynamic_viscosity(40), 0.0119, 0.005, "model.md 1.7");
  EXPECT_CHECK_RELATIVE("dynamic viscosity at 120 degC [Pa s]", oil.dynamic_viscosity(120), 0.0034, 0.015,
                        "model.md 1.7");
}

TEST(OilLaw, RefusesTemperatureOutsideItsWindow)
{
  const laws::Oil oil(test::rv1().fluid, 40);
  EXPECT_THROW(oil.kinematic_viscosity(151), InputError);
  EXPECT_THROW(oil.density(-56), InputError);
  EXPECT_NO_THROW(oil.kinematic_viscosity(150));
}

TEST(SpringTubeLaw, YoungsModulusAndDimensions)
{
  const auto v = test::rv1();
  // E12 with T_ref = 20 degC (C3)
  EXPECT_DOUBLE_EQ(laws::youngs_modulus(v.spring_tube, 20), 128e9);
  EXPECT_CHECK_RELATIVE("spring-tube modulus E12 at 120 degC [Pa]", laws::youngs_modulus(v.spring_tube, 120),
                        128e9 * (1 - 3.5e-4 * 100), 1e-14, "E12, T_ref = 20 degC (C3)");
  // E13: every dimension grows with alpha_s
  const auto g = laws::spring_tube_geometry(v.spring_tube, v.expansion, 120);
  EXPECT_CHECK_RELATIVE("spring-tube outer diameter E13 at 120 degC [m]", g.outer_diameter,
                        3.60e-3 * (1 + 17.8e-6 * 100), 1e-14, "E13");
  EXPECT_LT(relative(g.inner_diameter, 3.40e-3 * (1 + 17.8e-6 * 100)), 1e-14);
  EXPECT_LT(relative(g.length, 10.0e-3 * (1 + 17.8e-6 * 100)), 1e-14);
}

TEST(TorqueMotorLaw, AirGapsGrowAsModelSection13)
{
  // model.md 1.3: g_12 300.0 -> 307.8 um, g_34 300.0 -> 294.5 um from 40 to 120 degC;
  // dg_12/dT = +0.098 um/degC, dg_34/dT = -0.068 um/degC (printed to 0.1 um and 0.001 um/degC)
  const auto v = test::rv1();
  const auto g40 = laws::torque_motor_geometry(v.torque_motor, v.expansion, 40, 40);
  const auto g120 = laws::torque_motor_geometry(v.torque_motor, v.expansion, 120, 40);
  EXPECT_NEAR(g40.lower_gap, 300.0e-6, 1e-12);
  EXPECT_NEAR(g40.upper_gap, 300.0e-6, 1e-12);
  EXPECT_CHECK_ABSOLUTE("air gap g_12 E6 at 120 degC [um]", g120.lower_gap * 1e6, 307.8, 0.05, "model.md 1.3");
  EXPECT_CHECK_ABSOLUTE("air gap g_34 E7 at 120 degC [um]", g120.upper_gap * 1e6, 294.5, 0.05, "model.md 1.3");
  EXPECT_CHECK_ABSOLUTE("dg_12/dT [um/K]", (g120.lower_gap - g40.lower_gap) / 80 * 1e6, 0.098, 0.0005, "model.md 1.3");
  EXPECT_CHECK_ABSOLUTE("dg_34/dT [um/K]", (g120.upper_gap - g40.upper_gap) / 80 * 1e6, -0.068, 0.0005,
                        "model.md 1.3");
  EXPECT_LT(relative(g120.pivot_to_pole_distance, 14.8e-3 * (1 + 9e-6 * 80)), 1e-14);
  EXPECT_LT(relative(g120.magnet_area, 25e-6 * std::pow(1 + 11e-6 * 80, 2)), 1e-14);
}

TEST(TorqueMotorLaw, Remanence)
{
  // E8, D4: B_r(40) = 0.90 T, alpha_Br = -2.5e-4 -> 0.882 T at 120 degC
  const auto v = test::rv1();
  EXPECT_DOUBLE_EQ(laws::remanence(v.torque_motor, 40, 40), 0.90);
  EXPECT_CHECK_ABSOLUTE("remanence E8 at 120 degC [T]", laws::remanence(v.torque_motor, 120, 40), 0.882, 1e-15,
                        "E8, D4: 0.90 T, -2.5e-4/K");
  auto m = v.torque_motor;
  m.irreversible_loss = 0.1;
  EXPECT_NEAR(laws::remanence(m, 40, 40), 0.81, 1e-15);
}

TEST(PilotStageLaw, NullGapOfAnAluminiumBody)
{
  // model.md 2.3: steel chain temperature-neutral; aluminium body (23e-6) gives about +0.08 um/degC
  const auto steel = test::rv1();
  const auto g = laws::pilot_stage_geometry(steel.pilot, steel.armature, steel.expansion, 120, 40);
  EXPECT_NEAR(g.null_gap, 40e-6, 1e-12);
  auto aluminium = test::rv1();
  aluminium.expansion.body = 23e-6; // `Thermal expansion/Body' = 23e-6
  const auto ga = laws::pilot_stage_geometry(aluminium.pilot, aluminium.armature, aluminium.expansion, 120, 40);
  // "about 0.08": within 5 %
  EXPECT_CHECK_RELATIVE("null gap of an aluminium body, dx0/dT [um/K]", (ga.null_gap - 40e-6) / 80 * 1e6, 0.08, 0.05,
                        "model.md 2.3");
}
