#include "flow/fv/momentum_equation.h"

#include <Eigen/UmfPackSupport>

#include <cmath>
#include <stdexcept>

namespace servodrift::flow
{
  namespace
  {
    /// D~ = V/(a_P - sum a_nb) needs a_P - sum a_nb clearly positive; else SIMPLE's V/a_P
    constexpr double simplec_denominator_floor = 1e-12;
  } // namespace

  struct MomentumEquation::DirectSolvers
  {
    std::array<Eigen::UmfPackLU<SparseMatrix>, 2> lu;
    SparseMatrix column_major; ///< UMFPACK takes its matrix by columns
  };

  MomentumEquation::MomentumEquation(const FvMesh &mesh_, const MatrixPattern &pattern, const FluidProperties &fluid_,
                                     const FlowSolverParameters &settings_)
    : mesh(mesh_)
    , fluid(fluid_)
    , settings(settings_)
    , equation{FvMatrix(mesh_, pattern), FvMatrix(mesh_, pattern)}
    , D_rhie_chow(mesh_.n_cells(), 0.0)
    , D_tilde(mesh_.n_cells(), 0.0)
    , direct(std::make_unique<DirectSolvers>())
  {}

  MomentumEquation::~MomentumEquation() = default;

  MomentumEquation::Residuals MomentumEquation::assemble(const FlowState &s, const BoundaryConditions &boundaries,
                                                         const TurbulenceModel &turbulence,
                                                         const std::vector<double> &convecting_flux, const TimeTerm *time)
  {
    // the transpose part of the turbulent stress needs both velocity gradients
    std::vector<Vector2> grad_u, grad_v;
    if (turbulence.turbulent())
      grad_u = mesh.gradient(s.u, s.u_b), grad_v = mesh.gradient(s.v, s.v_b);
    Residuals r{};
    double scale_v = 0;
    r.u = assemble_component(0, s, boundaries, turbulence, convecting_flux, grad_u, grad_v, time, r.scale);
    r.v = assemble_component(1, s, boundaries, turbulence, convecting_flux, grad_u, grad_v, time, scale_v);
    return r;
  }

  double MomentumEquation::assemble_component(int i, const FlowState &s, const BoundaryConditions &boundaries,
                                              const TurbulenceModel &turbulence,
                                              const std::vector<double> &convecting_flux,
                                              const std::vector<Vector2> &grad_u, const std::vector<Vector2> &grad_v,
                                              const TimeTerm *time, double &scale)
  {
    const std::size_t n = mesh.n_cells();
    const double mu = fluid.viscosity;
    const std::vector<double> &phi = i == 0 ? s.u : s.v, &phi_b = i == 0 ? s.u_b : s.v_b;
    const std::vector<double> &other = i == 0 ? s.v : s.u;
    const std::vector<double> &mu_face = turbulence.face_viscosity(), &mu_t = turbulence.viscosity();
    FvMatrix &eq = equation[i];
    // convection and diffusion with mu + mu_t
    eq.assemble_convection_diffusion(phi, phi_b, mu_face, convecting_flux, boundaries, settings.convection);
    mesh.for_each_boundary_face([&](std::size_t f, unsigned int P) {
      if (boundaries.kind(f) != BoundaryCondition::Kind::symmetry)
        return;
      // symmetry plane, no shear: only the normal component diffuses towards zero (couples u and v)
      const Vector2 &nrm = mesh.face_normal[f];
      const double a = mu_face[f] * mesh.face_area[f] / mesh.distance_to_face(f), nc = nrm[i], no = nrm[1 - i];
      eq.diagonal[P] += a * nc * nc;
      eq.b[P] -= a * nc * no * other[P];
    });
    if (turbulence.turbulent())
      // div(mu_t (grad u)^T), explicitly: it vanishes for a constant viscosity in planar flow, not for mu_t
      mesh.for_each_interior_face([&](std::size_t f, unsigned int P, unsigned int N) {
        const double mut = mesh.interpolate(f, mu_t);
        const Vector2 S = mesh.face_area[f] * mesh.face_normal[f];
        const double gu = mesh.interpolate(f, grad_u)[i], gv = mesh.interpolate(f, grad_v)[i];
        const double t = mut * (gu * S.x() + gv * S.y());
        eq.b[P] += t, eq.b[N] -= t;
      });
    for (std::size_t c = 0; c < n; ++c)
      {
        const double V = mesh.cell_volume[c];
        eq.b[c] -= s.grad_p[c][i] * V; // -grad p, explicit
        if (time)
          eq.diagonal[c] += time->diagonal[c], eq.b[c] += time->source[i][c];
        if (i == 1 && mesh.geometry == Geometry::axisymmetric)
          {
            // hoop: -mu v/r^2 of the Laplacian form; -2 mu_t v/r^2 for the turbulent stress, whose
            // transpose part is explicit above
            const double r = mesh.cell_center[c].y();
            eq.diagonal[c] += (mu + 2 * (turbulence.turbulent() ? mu_t[c] : 0.0)) * V / (r * r);
          }
      }
    std::vector<double> speed(n);
    for (std::size_t c = 0; c < n; ++c)
      speed[c] = std::hypot(s.u[c], s.v[c]);
    const double alpha = settings.velocity_relaxation;
    const double residual = eq.relax(phi, alpha, speed, scale);
    if (i == 0)
      for (std::size_t c = 0; c < n; ++c)
        {
          const double a_P = eq.diagonal[c] / alpha; // the relaxed diagonal of the x equation
          D_rhie_chow[c] = mesh.cell_volume[c] / a_P;
          // SIMPLEC: V/(a_P - sum a_nb); the boundary and relaxation terms keep it positive
          const double denominator = a_P - eq.neighbour_sum[c];
          D_tilde[c] = denominator > simplec_denominator_floor * a_P ? mesh.cell_volume[c] / denominator : D_rhie_chow[c];
        }
    return residual;
  }

  void MomentumEquation::solve(FlowState &s, bool first_iteration)
  {
    for (int i = 0; i < 2; ++i)
      {
        std::vector<double> &phi = i == 0 ? s.u : s.v;
        FvMatrix &eq = equation[i];
        if (settings.momentum_solver != FlowSolverParameters::MomentumSolver::direct)
          {
            eq.solve(phi, settings, settings.momentum_solver, "momentum");
            continue;
          }
        auto &lu = direct->lu[i];
        direct->column_major = eq.A;
        if (first_iteration)
          lu.analyzePattern(direct->column_major);
        lu.factorize(direct->column_major);
        if (lu.info() != Eigen::Success)
          throw std::runtime_error("UMFPACK could not factorise the momentum matrix");
        Eigen::Map<Eigen::VectorXd> x(phi.data(), mesh.n_cells());
        x = lu.solve(eq.b);
        if (lu.info() != Eigen::Success)
          throw std::runtime_error("UMFPACK momentum solve failed");
      }
  }
} // namespace servodrift::flow
