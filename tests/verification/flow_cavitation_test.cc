// Verification of the cavitation model's phase changes (flow/fv/cavitation_model.h; doc/method.md,
// "Cavitation"), on three cells in a row with a prescribed flux through them (no solver: the model's
// own rules, in closed form).
//
// A liquid cell that the pressure correction stretches below p_cav cavitates and holds p_cav. Its
// fluxes were corrected as a liquid cell's, so they balance: in a time step the same iteration's
// liquid-fraction update must not return it to the liquid (in/out = 1), or it lies on p_cav in every
// iteration with the correction lost and its imbalance unchanged, the fixed point that capped the
// hot Launder-Sharma orifice's time steps (doc/validation.md, "Robustness"). In the next iteration
// its balance decides: as much mixture in as out, liquid again; more out than in, cavitating with
// the mixture ratio of its balance with storage S = rho V/dt (implicit Euler, liquid before):
// m = (in + S)/(out + S). A steady iteration returns it at once (no storage to hold its mass).
#include "flow/fv/cavitation_model.h"
#include "flow/fv/flow_state.h"
#include "tests/support/checks.h"
#include "tests/verification/flow_test_domains.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace servodrift::flow
{
  using namespace domains;

  namespace
  {
    /// The flux q [kg/s per m] along x through every x-face of a planar mesh (out of the owner
    /// positive), times `stretch' on the faces whose owner or neighbour is `cell' and that lie
    /// downstream of it.
    std::vector<double> flux_along_x(const FvMesh &mesh, double q, std::size_t cell = 0, double stretch = 1)
    {
      std::vector<double> F(mesh.n_faces(), 0.0);
      for (std::size_t f = 0; f < mesh.n_faces(); ++f)
        {
          F[f] = q * mesh.face_normal[f].x() * mesh.face_area[f];
          const bool touches = mesh.owner[f] == cell || (mesh.neighbour[f] >= 0 && std::size_t(mesh.neighbour[f]) == cell);
          if (touches && mesh.face_center[f].x() > mesh.cell_center[cell].x())
            F[f] *= stretch;
        }
      return F;
    }
  } // namespace

  TEST(FlowCavitation, ACellTheCorrectionMadeCavitateKeepsItForThatIterationOfAStep)
  {
    const FvMesh mesh = rectangle(Geometry::planar, 0, 3e-3, 0, 1e-3, 3, 1);
    ASSERT_EQ(mesh.n_cells(), 3u);
    std::size_t middle = 0;
    for (std::size_t c = 0; c < 3; ++c)
      if (std::abs(mesh.cell_center[c].x() - 1.5e-3) < 1e-9)
        middle = c;
    constexpr double r = 1e-3, p_cav = -1e5;
    CavitationModel cavitation(mesh, r);
    cavitation.enable(p_cav);
    std::vector<double> p(3, 0.0);
    const std::vector<double> balanced = flux_along_x(mesh, 1.0);
    constexpr double density = 850;
    TimeLevel euler;
    euler.dt = 1e-6;
    euler.last.mixture.assign(3, 1.0);

    cavitation.set_cell_pressure(p, middle, p_cav - 1e5); // the correction stretched it below p_cav
    ASSERT_TRUE(cavitation.cell_cavitates(middle));
    EXPECT_EQ(p[middle], p_cav);
    cavitation.update_liquid_fraction(balanced, &euler, density); // same iteration: not undone
    EXPECT_TRUE(cavitation.cell_cavitates(middle));
    EXPECT_DOUBLE_EQ(cavitation.gamma[middle], 1.0);
    cavitation.update_liquid_fraction(balanced, &euler, density); // next iteration: balanced, liquid again
    EXPECT_FALSE(cavitation.cell_cavitates(middle));
    EXPECT_EQ(cavitation.gamma[middle], 1.0);

    // stretched again, and the next iteration's fluxes at p_cav take a quarter more out than in
    cavitation.set_cell_pressure(p, middle, p_cav - 1e5);
    cavitation.update_liquid_fraction(balanced, &euler, density);
    const std::vector<double> outflow = flux_along_x(mesh, 1.0, middle, 1.25);
    cavitation.update_liquid_fraction(outflow, &euler, density);
    ASSERT_TRUE(cavitation.cell_cavitates(middle));
    double in = 0, out = 0; // the x-faces' |F| into and out of the middle cell
    for (std::size_t f = 0; f < mesh.n_faces(); ++f)
      if (mesh.owner[f] == middle || (mesh.neighbour[f] >= 0 && std::size_t(mesh.neighbour[f]) == middle))
        (mesh.face_center[f].x() > mesh.cell_center[middle].x() ? out : in) += std::abs(outflow[f]);
    ASSERT_NEAR(out / in, 1.25, 1e-12);
    const double storage = density * mesh.cell_volume[middle] / euler.dt;
    const double m = (in + storage) / (out + storage);
    EXPECT_CHECK_ABSOLUTE("liquid fraction of a cell the correction made cavitate, a quarter more out than in, "
                          "implicit Euler",
                          cavitation.gamma[middle], (m - r) / (1 - r), 1e-12, "m = (in + S)/(out + S), S = rho V/dt");

    // a steady iteration returns a balanced cell to the liquid in the iteration that made it cavitate
    CavitationModel steady(mesh, r);
    steady.enable(p_cav);
    steady.set_cell_pressure(p, middle, p_cav - 1e5);
    steady.update_liquid_fraction(balanced);
    EXPECT_FALSE(steady.cell_cavitates(middle));
    // a liquid cell that stays above p_cav is untouched
    for (std::size_t c = 0; c < 3; ++c)
      EXPECT_EQ(cavitation.cell_cavitates(c), c == middle) << "cell " << c;
  }
} // namespace servodrift::flow
