#pragma once
// The SIMPLEC pressure correction (OpenFOAM's pEqn.H; doc/method.md, "Flow core", SIMPLEC): from
// the Rhie-Chow fluxes F* of the predicted velocities,
//   sum_f m_f c~_f (p'_N - p'_P) = sum_f m_f F*_f,   c~_f = rho D~_f |S|/(n . d),  D~ = V/(a_P - sum a_nb),
// symmetric positive definite; then F = F* - c~_f (p'_N - p'_P) (conservative), u -= D~ grad p',
// p += alpha_p p'. m_f is the upwind mixture density ratio where cells cavitate (1 otherwise); a
// cavitating cell holds p = p_cav in place of its continuity.
#include "flow/fv/cavitation_model.h"
#include "flow/fv/fv_matrix.h"

#include <memory>
#include <vector>

namespace servodrift::flow
{
  class PressureEquation
  {
  public:
    /// The symbolic analysis of the pressure matrix (CHOLMOD), once per mesh.
    PressureEquation(const FvMesh &mesh, const MatrixPattern &pattern, double density);
    ~PressureEquation();

    /// Corrects the fluxes F (in: F*, out: conservative), the velocities and the pressure of
    /// `state' (the pressure by `relaxation' times the correction, through the cavitation model);
    /// returns sum |m F*| of the liquid cells' imbalances before the correction. In a time step
    /// (`time') a liquid cell's mass balance holds the change of its mass since the old levels.
    double correct(std::vector<double> &F, FlowState &state, const std::vector<double> &D_simplec,
                   const BoundaryConditions &boundaries, CavitationModel &cavitation, double relaxation,
                   const TimeLevel *time = nullptr);

  private:
    const FvMesh &mesh;
    const MatrixPattern &pattern;
    double density;
    struct Solver;
    std::unique_ptr<Solver> solver;
  };
} // namespace servodrift::flow
