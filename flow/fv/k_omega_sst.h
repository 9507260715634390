#pragma once
// Menter's k-omega shear-stress transport model in its 2003 form (Menter, Kuntz and Langtry, "Ten
// years of industrial experience with the SST turbulence model", Turbulence, Heat and Mass Transfer
// 4, 2003, 625-632; doc/method.md, "Turbulence"), integrated to the wall:
//   div(rho u k) = div((mu + sigma_k mu_t) grad k) + P~ - beta* rho omega k
//   div(rho u w) = div((mu + sigma_w mu_t) grad w) + alpha rho S^2 - beta rho w^2
//                  + 2 (1 - F1) rho sigma_w2 grad k . grad w / w
//   P = mu_t S^2, P~ = min(P, 10 beta* rho k omega) (the production limiter), S^2 = 2 S_ij S_ij
//   mu_t = rho a1 k / max(a1 omega, S F2)
// with each constant blended phi = F1 phi_1 + (1 - F1) phi_2 between the k-omega set near walls and
// the k-epsilon set outside (F1, F2 of the wall distance). Walls: k = 0; the cells at a wall hold the
// viscous sublayer's omega = 6 nu/(beta_1 y^2) at their centre's distance y (resolved: the first cell
// at y+ of order 1, no wall function), and the wall face Menter's 10 x 6 nu/(beta_1 y^2) for the
// gradients. An inflow brings
// k = 3/2 (I u_n)^2, omega = sqrt(k)/(C_mu^(1/4) L); an outflow, the axis and a symmetry plane take the
// cell's values. The sinks and a negative cross-diffusion are implicit.
// Continuation fields are k and epsilon = beta* k omega, as the k-epsilon models', so that a case can
// go on from another model's fields.
#include "flow/fv/turbulence_model.h"

#include <vector>

namespace servodrift::flow
{
  class KOmegaSST : public TurbulenceModel
  {
  public:
    KOmegaSST(const FvMesh &mesh, const FluidProperties &fluid, const BoundaryConditions &boundaries,
              const FlowSolverParameters &settings, const MatrixPattern &pattern);
    bool turbulent() const override { return true; }
    /// The residuals are those of k and omega (reported as k and epsilon).
    TurbulenceResiduals correct(const FlowState &state, const std::vector<double> &convecting_flux,
                                const TimeLevel *time = nullptr) override;
    /// k and omega
    std::vector<std::vector<double>> transported_fields() const override;
    void store(FlowFields &fields) const override;
    void restore(const FlowFields &fields) override;
    void scale_pressure_level(double s) override;
    std::vector<std::vector<double> *> accelerated_fields() override;
    void bound_accelerated(const std::vector<std::vector<double>> &before) override;
    std::vector<std::pair<std::string, const std::vector<double> *>> output_fields() const override;

  private:
    void boundary_values(const FlowState &state, double &k_inflow, double &omega_inflow);
    /// F1 and F2 of each cell from k, omega (at least `omega_floor'), the gradients of k and ln omega
    /// and the wall distance.
    void blending(const std::vector<Vector2> &grad_k, const std::vector<Vector2> &grad_ln_omega, double omega_floor);

    FlowSolverParameters settings;
    std::vector<double> wall_distance;    ///< per cell [m]
    std::vector<double> k, omega;         ///< per cell [m^2/s^2], [1/s]
    std::vector<double> k_b, omega_b;     ///< per boundary face
    std::vector<double> F1, F2;           ///< blending functions per cell [1]
    /// the cells with a wall face, and their normal distance to it (the nearest) [m]
    std::vector<std::pair<unsigned int, double>> wall_cells;
    FvMatrix k_equation, omega_equation;
  };
} // namespace servodrift::flow
