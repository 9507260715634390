// Field level of the spring tube (issue 6; D12, model.md 1.6, 4.3, C3, C11): axisymmetric elasticity
// with harmonic n = 1 against the beam closed forms, model.md's independent 3D figure, its own mesh
// sequence, the temperature laws E12-E13, and the yield strength.
#include "common/thermal_laws.h"
#include "structure/spring_tube_beam.h"
#include "structure/spring_tube_field.h"
#include "structure/spring_tube_stage.h"
#include "tests/support/checks.h"
#include "tests/support/test_support.h"

#include <gtest/gtest.h>

#include <vtkCellData.h>
#include <vtkCellSizeFilter.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <cstdio>
#include <fstream>

using namespace servodrift;
using namespace servodrift::structure;
using test::relative;

namespace
{
  constexpr double pi = 3.14159265358979323846;

  ValveDescription field_valve(std::vector<std::string> overrides = {})
  {
    overrides.insert(overrides.begin(), "Spring tube/Model level=field");
    return test::valve(overrides);
  }

  /// Timoshenko tip deflection under a tip shear: l^3/(3 E I) + l/(kappa G A), with Cowper's shear
  /// coefficient of a thin-walled circular tube kappa = 2 (1 + nu)/(4 + 3 nu).
  double timoshenko_shear_compliance(const BeamTube &b, double nu, double D, double d)
  {
    const double kappa = 2 * (1 + nu) / (4 + 3 * nu);
    const double G = b.youngs_modulus / (2 * (1 + nu)), A = pi * (D * D - d * d) / 4;
    return std::pow(b.length, 3) / (3 * b.youngs_modulus * b.second_moment) + b.length / (kappa * G * A);
  }
} // namespace

TEST(SpringTubeField, SlenderTubeIsTheBeam)
{
  // l/D = 20: the ends' hoop restraint is confined to a few sqrt(R t) = 0.4 mm of 72 mm, so the
  // tube is a beam. Issue 6: K_a within 1 % of E I/l. The cross compliance l^2/(2 E I) and the
  // shear compliance (Timoshenko, 0.4 % above Euler-Bernoulli here) to the same 1 %.
  const auto v = field_valve({"Spring tube/Length=72e-3"});
  const auto field = spring_tube_field(v, 20);
  const BeamTube b = beam_tube(v, 20);
  const auto C = field->compliance();
  const double EI = b.youngs_modulus * b.second_moment, l = b.length;
  std::printf("l/D = 20: K_a %.5f N*m/rad, E I/l %.5f (%+.3f %%); C_MV %+.3f %%, C_VV %+.3f %% (Timoshenko)\n",
              field->rotational_stiffness(), b.rotational_stiffness,
              100 * (field->rotational_stiffness() / b.rotational_stiffness - 1), 100 * (C[0][1] / (l * l / (2 * EI)) - 1),
              100 * (C[1][1] / timoshenko_shear_compliance(b, 0.3, 3.6e-3, 3.4e-3) - 1));
  EXPECT_CHECK_RELATIVE("K_a, l/D = 20 [N m/rad]", field->rotational_stiffness(), b.rotational_stiffness, 0.01,
                        "E I/l (issue 6)");
  EXPECT_CHECK_RELATIVE("C_MV, l/D = 20 [mrad/N]", 1e3 * C[0][1], 1e3 * l * l / (2 * EI), 0.01, "l^2/(2 E I)");
  EXPECT_CHECK_RELATIVE("C_VV, l/D = 20 [um/N]", 1e6 * C[1][1],
                        1e6 * timoshenko_shear_compliance(b, 0.3, 3.6e-3, 3.4e-3), 0.01, "Timoshenko, Cowper's kappa");
  // Maxwell-Betti: the stiffness of the top is symmetric, to the round-off of a(u_i, u_j) summed over
  // a matrix whose entries span about 8 decades (measured 2e-9)
  const auto S = field->stiffness();
  EXPECT_CHECK_RELATIVE("S_MV of the top, l/D = 20 [N]", S[0][1], S[1][0], 1e-7, "Maxwell-Betti: S_VM");
}

TEST(SpringTubeField, RV1AgainstE11AndTheIndependent3DModel)
{
  // RV-1 (l/D = 2.8) at 40 degC. model.md C3: an independent 3D FEM with a clamped base and a rigid
  // top gives 21.57 N*m/rad, 0.6 % stiffer than E I/l = 21.44 (C11: the clamped and rigid ends stop
  // the wall's Poisson hoop strain). The printed 21.57 has 4 digits: 0.3 % covers its rounding and
  // the other model's discretisation.
  const auto v = field_valve();
  const auto field = spring_tube_field(v, 40);
  const BeamTube b = beam_tube(v, 40);
  const double K = field->rotational_stiffness(), excess = K / b.rotational_stiffness - 1;
  std::printf("RV-1 at 40 degC: K_a %.4f N*m/rad (E11 %.4f, %+.3f %%), %u cells, %u unknowns\n", K,
              b.rotational_stiffness, 100 * excess, field->n_cells(), field->n_dofs());
  EXPECT_CHECK_RELATIVE("K_a at 40 degC [N m/rad]", K, 21.57, 0.003, "independent 3D FEM, model.md C3");
  EXPECT_CHECK_AT_LEAST("K_a / (E I/l) - 1 at 40 degC [%]", 100 * excess, 0.3, "C11: the ends' hoop restraint");
  EXPECT_CHECK_AT_MOST("K_a / (E I/l) - 1 at 40 degC [%]", 100 * excess, 1, "C11: the ends' hoop restraint");
  // at l/D = 2.8 the tip shear compliance is Timoshenko's (shear is 19 % of it) to 2 %; the moment
  // compliances are the beam's to 1 %
  const auto C = field->compliance();
  const double EI = b.youngs_modulus * b.second_moment, l = b.length;
  const double timoshenko = timoshenko_shear_compliance(b, 0.3, 3.6e-3 * (1 + 17.8e-6 * 20), 3.4e-3 * (1 + 17.8e-6 * 20));
  std::printf("  C_MV %+.3f %% of l^2/(2EI), C_VV %+.3f %% of Timoshenko, %+.1f %% of Euler-Bernoulli\n",
              100 * (C[0][1] / (l * l / (2 * EI)) - 1), 100 * (C[1][1] / timoshenko - 1),
              100 * (C[1][1] / (l * l * l / (3 * EI)) - 1));
  EXPECT_CHECK_RELATIVE("C_MV at 40 degC [mrad/N]", 1e3 * C[0][1], 1e3 * l * l / (2 * EI), 0.01, "l^2/(2 E I)");
  EXPECT_CHECK_RELATIVE("C_VV at 40 degC [um/N]", 1e6 * C[1][1], 1e6 * timoshenko, 0.02, "Timoshenko, Cowper's kappa");
}

TEST(SpringTubeField, MeshConvergence)
{
  // Issue 6: three meshes (resolution 1, 2, 4: 4, 8, 16 layers through the wall), below 0.5 %
  // change between the two finest; for the plain tube and for one with a base flange and a top
  // collar (re-entrant corners, whose stress is singular but whose stiffness converges).
  for (const bool ends : {false, true})
    {
      std::vector<double> K;
      for (const char *resolution : {"1", "2", "4"})
        {
          std::vector<std::string> o{std::string("Spring tube/Field mesh resolution=") + resolution};
          if (ends)
            o.insert(o.end(), {"Spring tube/Base flange diameter=8e-3", "Spring tube/Base flange height=2e-3",
                               "Spring tube/Top collar diameter=6e-3", "Spring tube/Top collar height=2e-3"});
          K.push_back(spring_tube_field(field_valve(o), 40)->rotational_stiffness());
        }
      std::printf("%s: K_a %.6f, %.6f, %.6f N*m/rad; changes %+.4f %%, %+.4f %%\n",
                  ends ? "flange and collar" : "plain tube", K[0], K[1], K[2], 100 * (K[1] / K[0] - 1),
                  100 * (K[2] / K[1] - 1));
      const std::string tube = ends ? "flange and collar" : "plain tube";
      EXPECT_CHECK_RELATIVE("K_a at resolution 4, " + tube + " [N m/rad]", K[2], K[1], 0.005,
                            "resolution 2 (issue 6)");
      // and it does converge: the finest change is smaller than the coarser one
      EXPECT_CHECK_AT_MOST("|K_a(4) - K_a(2)|, " + tube + " [N m/rad]", std::abs(K[2] - K[1]),
                           std::abs(K[1] - K[0]) + 1e-12 * K[2], "|K_a(2) - K_a(1)|");
    }
}

TEST(SpringTubeField, FlangeAndCollarMakeTheTubeSofter)
{
  // model.md 4.3: flanges and the armature seat make the real stiffness lower than a tube clamped at
  // its base and rigid at its top (the junctions turn). With elastic ends of one piece with the
  // tube, K_a must fall, and by less than the typical 5-15 % of fillets and press fits together.
  const double plain = spring_tube_field(field_valve(), 40)->rotational_stiffness();
  const double ends = spring_tube_field(field_valve({"Spring tube/Base flange diameter=8e-3",
                                                     "Spring tube/Base flange height=2e-3",
                                                     "Spring tube/Top collar diameter=6e-3",
                                                     "Spring tube/Top collar height=2e-3"}),
                                         40)
                        ->rotational_stiffness();
  std::printf("flange 8 x 2 mm and collar 6 x 2 mm: K_a %.4f vs %.4f N*m/rad (%+.2f %%)\n", ends, plain,
              100 * (ends / plain - 1));
  EXPECT_CHECK_AT_MOST("K_a with flange and collar / plain tube", ends / plain, 1, "model.md 4.3: softer");
  EXPECT_CHECK_AT_LEAST("K_a with flange and collar / plain tube", ends / plain, 0.85, "model.md 4.3: by < 15 %");
}

TEST(SpringTubeField, TemperatureSlopeC11)
{
  // model.md 1.6, C11: d ln K_a/dT = -eta + 3 alpha_s at the reference 20 degC (issue 6: within
  // 2 %), from the FE at 19 and 21 degC; and the exact ratio (1 - eta dT)(1 + alpha_s dT)^3 at 40 and
  // 120 degC (the FE scales exactly with E and with the length cubed: same mesh topology, 1e-8).
  const auto v = field_valve();
  const auto K = [&](const ValveDescription &valve, double T) {
    return spring_tube_field(valve, T)->rotational_stiffness();
  };
  const double slope = (std::log(K(v, 21)) - std::log(K(v, 19))) / 2;
  const double expected = -3.5e-4 + 3 * 17.8e-6;
  std::printf("RV-1: d ln K_a/dT at 20 degC %.5e /degC (-eta + 3 alpha_s %.5e)\n", slope, expected);
  EXPECT_CHECK_RELATIVE("d ln K_a/dT at 20 degC, FE at 19 and 21 degC [1e-6/degC]", 1e6 * slope, 1e6 * expected, 0.02,
                        "C11: -eta + 3 alpha_s (issue 6)");
  for (double T : {40.0, 120.0})
    {
      const double dT = T - 20;
      EXPECT_CHECK_RELATIVE("K_a(" + format_number(T) + ")/K_a(20)", K(v, T) / K(v, 20),
                            (1 - 3.5e-4 * dT) * std::pow(1 + 17.8e-6 * dT, 3), 1e-8,
                            "E12, E13: (1 - eta dT)(1 + alpha_s dT)^3");
    }
  // the paper preset's literal eta = 0.04 alpha_s: the opposite sign, +2.96 alpha_s (1.6)
  const auto paper = field_valve({"Spring tube/Modulus temperature coefficient=7.12e-7"});
  const double paper_slope = (std::log(K(paper, 21)) - std::log(K(paper, 19))) / 2;
  std::printf("paper preset: d ln K_a/dT %.5e /degC (+2.96 alpha_s %.5e)\n", paper_slope, 2.96 * 17.8e-6);
  EXPECT_GT(paper_slope, 0);
  EXPECT_CHECK_RELATIVE("d ln K_a/dT at 20 degC, paper eta = 0.04 alpha_s [1e-6/degC]", 1e6 * paper_slope,
                        1e6 * (3 * 17.8e-6 - 7.12e-7), 0.02, "model.md 1.6: 3 alpha_s - eta");
}

TEST(SpringTubeField, StressAtRatedDeflection)
{
  // The flapper on its nozzle (x_f = x0 = 40 um, r = 10 mm: theta = 4 mrad) under the pure moment
  // K_a theta. At mid-length the axial stress at the outer fibre in the bending plane is the beam's
  // -M R/I (compression on the +x side for a moment that bends the tube toward +x; 1 %: the Poisson
  // hoop restraint is gone there). Beside the ends (one wall thickness away) the von Mises stress is
  // above M R/I (the end restraint), converged on the default mesh to 3 % of a mesh 4 times finer
  // (measured 2.1 %), and below the BeCu yield strength of 1 GPa. At the corners of the perfect
  // clamp the stress is singular: larger, and growing with refinement.
  const auto v = field_valve();
  const auto field = spring_tube_field(v, 40);
  const BeamTube b = beam_tube(v, 40);
  const double theta = rated_armature_angle(v);
  EXPECT_LT(relative(theta, 40e-6 / 10e-3), 1e-12);
  const TopLoad rated{field->rotational_stiffness() * theta, 0};
  EXPECT_LT(relative(field->top_motion(rated)[0], theta), 1e-9);
  const double nominal = rated.moment * b.outer_radius / b.second_moment;
  const double mid = field->axial_stress(rated, b.outer_radius, b.length / 2);
  const double wall = b.outer_radius - 1.7e-3 * (1 + 17.8e-6 * 20);
  const StressPeak beside = field->peak_stress(rated, wall), corner = field->peak_stress(rated);
  const auto fine = spring_tube_field(field_valve({"Spring tube/Field mesh resolution=4"}), 40);
  const StressPeak beside_fine = fine->peak_stress({fine->rotational_stiffness() * theta, 0}, wall);
  const StressPeak corner_fine = fine->peak_stress({fine->rotational_stiffness() * theta, 0});
  std::printf("rated deflection %.2f mrad, M %.4f N*m: sigma_zz mid-length %.2f MPa (-M R/I %.2f MPa, %+.3f %%)\n"
              "  von Mises beside the ends %.2f MPa (finer mesh %.2f) at r %.4f mm, z %.4f mm: yield margin %.2f\n"
              "  at the clamp's corners %.1f MPa (finer mesh %.1f: singular)\n",
              1e3 * theta, rated.moment, 1e-6 * mid, -1e-6 * nominal, 100 * (mid / -nominal - 1), 1e-6 * beside.von_mises,
              1e-6 * beside_fine.von_mises, 1e3 * beside.radius, 1e3 * beside.height, 1e9 / beside.von_mises,
              1e-6 * corner.von_mises, 1e-6 * corner_fine.von_mises);
  EXPECT_CHECK_RELATIVE("sigma_zz at mid-length, outer fibre [MPa]", 1e-6 * mid, -1e-6 * nominal, 0.01,
                        "beam: -M R/I");
  EXPECT_CHECK_AT_LEAST("von Mises beside the ends [MPa]", 1e-6 * beside.von_mises, 1e-6 * nominal, "M R/I");
  EXPECT_CHECK_AT_MOST("von Mises beside the ends [MPa]", 1e-6 * beside.von_mises, 1.3e-6 * nominal, "1.3 M R/I");
  EXPECT_CHECK_RELATIVE("von Mises beside the ends [MPa]", 1e-6 * beside.von_mises, 1e-6 * beside_fine.von_mises,
                        0.03, "mesh 4 times finer");
  EXPECT_CHECK_AT_LEAST("yield margin on the finer mesh", v.spring_tube.yield_strength / beside_fine.von_mises, 1,
                        "BeCu yield 1 GPa (issue 6)");
  EXPECT_CHECK_AT_LEAST("von Mises at the clamp's corners [MPa]", 1e-6 * corner.von_mises, 1e-6 * beside.von_mises,
                        "beside the ends");
  EXPECT_CHECK_AT_LEAST("von Mises at the clamp's corners, finer mesh [MPa]", 1e-6 * corner_fine.von_mises,
                        1e-6 * corner.von_mises, "default mesh: singular");
}

TEST(SpringTubeField, VtuHoldsTheRevolvedTube)
{
  // The VTU is the tube revolved into 3D: every hexahedron has a positive volume, the total is the
  // tube's volume (48 facets inscribe the circle: area factor sin(2 pi/48)/(2 pi/48)), and the top
  // carries the rigid motion: |u| at the top's outer edge in the bending plane is
  // sqrt(delta^2 + (theta R)^2).
  const auto v = field_valve();
  const auto field = spring_tube_field(v, 20);
  const TopLoad load{0.05, 0.2};
  const std::string file = v.output.directory + "/tube.vtu";
  field->write_vtu(file, load, 48);
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkUnstructuredGrid *grid = reader->GetOutput();
  ASSERT_EQ(grid->GetNumberOfCells(), 48 * static_cast<vtkIdType>(field->n_cells()));
  vtkNew<vtkCellSizeFilter> sizes;
  sizes->SetInputData(grid);
  sizes->ComputeSumOn();
  sizes->Update();
  auto *volume = vtkUnstructuredGrid::SafeDownCast(sizes->GetOutput())->GetCellData()->GetArray("Volume");
  double total = 0, smallest = 1;
  for (vtkIdType c = 0; c < volume->GetNumberOfTuples(); ++c)
    total += volume->GetTuple1(c), smallest = std::min(smallest, volume->GetTuple1(c));
  const double a = 2 * pi / 48, exact = pi * (1.8e-3 * 1.8e-3 - 1.7e-3 * 1.7e-3) * 10e-3;
  EXPECT_GT(smallest, 0);
  test::record_check("smallest hexahedron of the VTU [mm^3]", "positive, every cell", "> 0",
                     test::shown(1e9 * smallest));
  EXPECT_CHECK_RELATIVE("volume of the VTU [mm^3]", 1e9 * total, 1e9 * exact * std::sin(a) / a, 1e-6,
                        "48-facet tube");
  // the point at r = R, z = l, phi = 0
  const auto motion = field->top_motion(load);
  double at_top = -1;
  for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p)
    {
      double x[3];
      grid->GetPoint(p, x);
      if (std::abs(x[0] - 1.8e-3) < 1e-9 && std::abs(x[1]) < 1e-12 && std::abs(x[2] - 10e-3) < 1e-9)
        {
          double u[3];
          grid->GetPointData()->GetArray("displacement")->GetTuple(p, u);
          at_top = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
        }
    }
  EXPECT_CHECK_RELATIVE("|u| at the top's outer edge, phi = 0 [um]", 1e6 * at_top,
                        1e6 * std::hypot(motion[1], motion[0] * 1.8e-3), 1e-9,
                        "rigid top: sqrt(delta^2 + (theta R)^2)");
  ASSERT_NE(grid->GetPointData()->GetArray("von_Mises_stress"), nullptr);
}

TEST(SpringTubeField, StageWritesTheTableAndTheFields)
{
  // `servodrift structure' at the field level: the spring_tube table (Foundation schema), the field
  // summary and one VTU per temperature with a PVD collection.
  const auto v = field_valve({"Sweeps/Table temperatures=40, 120", "Sweeps/Drift temperatures=40, 120"});
  const Table table = compute_spring_tube_table(v);
  ASSERT_EQ(table.rows.size(), 2u);
  EXPECT_LT(relative(table.rows[0][1], spring_tube_field(v, 40)->rotational_stiffness()), 1e-12);
  EXPECT_EQ(table.rows[1][2], 0);
  for (const char *f : {"field_summary.csv", "spring_tube.pvd", "spring_tube_T40.vtu", "spring_tube_T120.vtu"})
    EXPECT_TRUE(std::ifstream(v.output.directory + "/structure/" + f).good()) << f;
}
