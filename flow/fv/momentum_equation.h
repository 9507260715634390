#pragma once
// The momentum equations (OpenFOAM's UEqn.H; doc/method.md, "Flow core"): for each component of u,
//   [d(rho_m u)/dt +] div(F u) - div(mu_eff grad u) = -grad p [+ div(mu_t (grad u)^T)] [- (mu + 2 mu_t) v/r^2 (radial)]
// assembled on the convecting fluxes F and the face viscosities of the turbulence model, the
// pressure gradient explicit, relaxed by alpha_u; with a time step the implicit Euler term
// rho_m V (u - u_old)/dt, rho_m the mixture's density (SimplecSolver::advance). From the x equation the coefficients of the
// pressure-velocity coupling: D = V/a_P (Rhie-Chow) and SIMPLEC's D~ = V/(a_P - sum a_nb).
#include "flow/fv/fv_matrix.h"
#include "flow/fv/turbulence_model.h"

#include <array>
#include <memory>
#include <vector>

namespace servodrift::flow
{
  class MomentumEquation
  {
  public:
    MomentumEquation(const FvMesh &mesh, const MatrixPattern &pattern, const FluidProperties &fluid,
                     const FlowSolverParameters &settings);
    ~MomentumEquation();

    /// sum |b - A u| and sum |b - A v| of the unrelaxed equations at the state's velocities, and
    /// sum a_P |u| of the x equation, what both are relative to.
    struct Residuals
    {
      double u, v, scale;
    };
    /// The implicit Euler term per cell: rho_m V/dt on the diagonal, rho_m,old V/dt u_old (x, y) on
    /// the right-hand side [kg/s per radian if axisymmetric; times m/s].
    struct TimeTerm
    {
      std::vector<double> diagonal;
      std::array<std::vector<double>, 2> source;
    };
    /// Assembles both components (then relaxed) and D, D~; `time' null: steady.
    Residuals assemble(const FlowState &state, const BoundaryConditions &boundaries, const TurbulenceModel &turbulence,
                       const std::vector<double> &convecting_flux, const TimeTerm *time = nullptr);
    /// The predicted velocities: u and v of `state' from the relaxed equations. With the direct
    /// solver, `first_iteration' of a solve renews UMFPACK's symbolic analysis (its strategy reads the
    /// values as well as the pattern).
    void solve(FlowState &state, bool first_iteration);

    /// The under-relaxation alpha_u of the next assemblies (default: `Velocity relaxation').
    void set_relaxation(double alpha) { settings.velocity_relaxation = alpha; }
    double relaxation() const { return settings.velocity_relaxation; }
    /// Holds both components' convection limiters (FvMatrix::hold_limiter) while `hold'.
    void hold_limiters(bool hold)
    {
      for (FvMatrix &eq : equation)
        eq.hold_limiter(hold);
    }
    /// The relaxed equation of component 0 (x) or 1 (y, radial).
    const FvMatrix &component(int i) const { return equation[i]; }
    const std::vector<double> &D() const { return D_rhie_chow; }
    const std::vector<double> &D_simplec() const { return D_tilde; }

  private:
    double assemble_component(int i, const FlowState &state, const BoundaryConditions &boundaries,
                              const TurbulenceModel &turbulence, const std::vector<double> &convecting_flux,
                              const std::vector<Vector2> &grad_u, const std::vector<Vector2> &grad_v, const TimeTerm *time,
                              double &scale);

    const FvMesh &mesh;
    FluidProperties fluid;
    FlowSolverParameters settings;
    std::array<FvMatrix, 2> equation;
    std::vector<double> D_rhie_chow, D_tilde;
    struct DirectSolvers;
    std::unique_ptr<DirectSolvers> direct;
  };
} // namespace servodrift::flow
