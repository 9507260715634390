#include "flow/fv/pressure_equation.h"

#include "common/error.h"
#include "flow/fv/continuity.h"
#include "flow/fv/rhie_chow.h"

#include <Eigen/CholmodSupport>
#include <Eigen/IterativeLinearSolvers>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace servodrift::flow
{
  namespace
  {
    using Cholesky = Eigen::CholmodSimplicialLDLT<SparseMatrix, Eigen::Lower>;

    /// Preconditions conjugate gradients with a Cholesky factorisation of a recent pressure matrix:
    /// the matrix changes slowly from one SIMPLEC iteration to the next, so an older factor solves
    /// the new system in a few iterations, and it is renewed only when they are no longer few.
    class FactorPreconditioner
    {
    public:
      using StorageIndex = int;
      enum
      {
        ColsAtCompileTime = Eigen::Dynamic,
        MaxColsAtCompileTime = Eigen::Dynamic
      };
      FactorPreconditioner() = default;
      template <typename M>
      FactorPreconditioner &analyzePattern(const M &) { return *this; }
      template <typename M>
      FactorPreconditioner &factorize(const M &) { return *this; }
      template <typename M>
      FactorPreconditioner &compute(const M &) { return *this; }
      template <typename Rhs>
      Rhs solve(const Rhs &b) const { return factor->solve(b); }
      Eigen::ComputationInfo info() const { return Eigen::Success; }
      const Cholesky *factor = nullptr;
    };

    /// CG steps with an old factor beyond which it is renewed
    constexpr unsigned int factor_renewal_iterations = 6;
    /// CG's relative residual: the corrected fluxes conservative to round-off
    constexpr double cg_tolerance = 1e-12;
    constexpr int max_cg_iterations = 200;
  } // namespace

  struct PressureEquation::Solver
  {
    SparseMatrix matrix;
    Cholesky factor;
    Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper, FactorPreconditioner> cg;
    bool have_factor = false;
    unsigned int last_cg_iterations = 0;
  };

  PressureEquation::PressureEquation(const FvMesh &mesh_, const MatrixPattern &pattern_, double density_)
    : mesh(mesh_)
    , pattern(pattern_)
    , density(density_)
    , solver(std::make_unique<Solver>())
  {
    solver->matrix = pattern.matrix;
    // the pattern's positions hold in this column-major copy (symmetric values; MatrixPattern)
    const auto &copy = solver->matrix;
    if (!std::equal(copy.innerIndexPtr(), copy.innerIndexPtr() + copy.nonZeros(), pattern.matrix.innerIndexPtr()))
      throw std::logic_error("flow: the pressure equation's pattern is not structurally symmetric");
    solver->factor.analyzePattern(solver->matrix); // once per mesh
    if (solver->factor.info() != Eigen::Success)
      throw std::runtime_error("flow: CHOLMOD symbolic analysis of the pressure equation failed");
    solver->cg.preconditioner().factor = &solver->factor;
  }

  PressureEquation::~PressureEquation() = default;

  double PressureEquation::correct(std::vector<double> &F, FlowState &s, const std::vector<double> &D_simplec,
                                   const BoundaryConditions &boundaries, CavitationModel &cavitation, double relaxation,
                                   const TimeLevel *time)
  {
    const std::size_t n = mesh.n_cells();
    const double rho = density;
    SparseMatrix &A = solver->matrix;
    double *value = A.valuePtr();
    std::fill(value, value + A.nonZeros(), 0.0);
    std::vector<double> diag(n, 0.0), coefficient(mesh.n_faces(), 0.0);
    // the mixture's mass balance: the upwind mixture density ratio m of each face (1 without
    // cavitation) weights flux and correction alike, so the matrix stays symmetric
    const std::vector<double> imbalance = cell_mass_imbalance(mesh, F, cavitation, time, rho);
    mesh.for_each_face(
      [&](std::size_t f, unsigned int P, unsigned int N) {
        const double m = cavitation.face_mixture_ratio(f, F[f]);
        coefficient[f] = face_coefficient(mesh, f, D_simplec, rho);
        value[pattern.owner_row[f]] = value[pattern.neighbour_row[f]] = -m * coefficient[f];
        diag[P] += m * coefficient[f], diag[N] += m * coefficient[f];
      },
      [&](std::size_t f, unsigned int P) {
        if (!boundaries.is_pressure_boundary(f))
          return;
        const double m = cavitation.face_mixture_ratio(f, F[f]);
        coefficient[f] = face_coefficient(mesh, f, D_simplec, rho); // p' = 0 there
        if (F[f] < 0)
          {
            // p_b = p_0 - F^2/(2 rho A^2) moves with the inflow: p_b' = -|F| F'/(rho A^2), so
            // F' = c (p_P' - p_b') gives F' = c p_P'/(1 + c |F|/(rho A^2)). Without it the
            // boundary pressure lags the flux and the iteration oscillates and diverges.
            const double area = mesh.face_area[f];
            coefficient[f] /= 1 + coefficient[f] * std::abs(F[f]) / (rho * area * area);
          }
        diag[P] += m * coefficient[f];
      });
    if (!boundaries.has_pressure_boundary())
      diag[0] *= 2; // a closed domain: tie p' of one cell to zero (p' is defined up to a constant)
    for (std::size_t c = 0; c < n; ++c)
      value[pattern.diagonal[c]] = diag[c];
    Eigen::VectorXd rhs(n);
    for (std::size_t c = 0; c < n; ++c)
      rhs[c] = -imbalance[c];
    const double sum = liquid_imbalance_sum(imbalance, cavitation);
    if (cavitation.enabled())
      {
        // a cavitating cell holds p = p_cav: its row is p' = p_cav - p, and its liquid neighbours
        // see that p' as known (moved to their right-hand side, symmetric elimination); the
        // liquid fraction balances its mass instead (CavitationModel::update_liquid_fraction)
        const double p_cav = cavitation.pressure_floor();
        mesh.for_each_interior_face([&](std::size_t f, unsigned int P, unsigned int N) {
          if (!cavitation.cavitating[P] && !cavitation.cavitating[N])
            return;
          const double a = -value[pattern.owner_row[f]]; // m c
          if (!cavitation.cavitating[P])
            rhs[P] += a * (p_cav - s.p[N]);
          if (!cavitation.cavitating[N])
            rhs[N] += a * (p_cav - s.p[P]);
          value[pattern.owner_row[f]] = value[pattern.neighbour_row[f]] = 0;
        });
        for (std::size_t c = 0; c < n; ++c)
          if (cavitation.cavitating[c])
            {
              value[pattern.diagonal[c]] = 1;
              rhs[c] = p_cav - s.p[c];
            }
      }
    // Conjugate gradients preconditioned by the Cholesky factor of a recent matrix: a new numeric
    // factorisation (the symbolic one is reused) when the factor has aged so that CG needs more than
    // a few steps. The tight tolerance keeps the corrected fluxes conservative to round-off.
    Solver &S = *solver;
    auto refactorize = [&] {
      S.factor.factorize(A);
      if (S.factor.info() != Eigen::Success)
        throw std::runtime_error("CHOLMOD could not factorise the pressure-correction matrix");
      S.have_factor = true;
    };
    const bool fresh = !S.have_factor || S.last_cg_iterations > factor_renewal_iterations;
    if (fresh)
      refactorize();
    S.cg.setTolerance(cg_tolerance);
    S.cg.setMaxIterations(max_cg_iterations);
    S.cg.compute(A);
    Eigen::VectorXd pc = S.cg.solve(rhs);
    if (S.cg.info() != Eigen::Success && !fresh)
      {
        // the matrix has moved too far from the old factor's: renew it and solve again
        refactorize();
        pc = S.cg.solve(rhs);
      }
    S.last_cg_iterations = static_cast<unsigned int>(S.cg.iterations());
    if (S.cg.info() != Eigen::Success)
      throw std::runtime_error("the pressure-correction solve did not converge (" +
                               std::to_string(S.last_cg_iterations) + " CG iterations, relative residual " +
                               format_number(S.cg.error()) + ")");

    // conservative flux correction
    mesh.for_each_face([&](std::size_t f, unsigned int P, unsigned int N) { F[f] -= coefficient[f] * (pc[N] - pc[P]); },
                       [&](std::size_t f, unsigned int P) {
                         if (boundaries.is_pressure_boundary(f))
                           F[f] += coefficient[f] * pc[P];
                       });
    // velocity and pressure correction: p' is 0 at pressure boundaries, zero-gradient elsewhere
    std::vector<double> pc_cells(pc.data(), pc.data() + n), pc_b(mesh.n_faces(), 0.0);
    mesh.for_each_boundary_face([&](std::size_t f, unsigned int P) {
      if (!boundaries.is_pressure_boundary(f))
        pc_b[f] = pc[P];
    });
    const std::vector<Vector2> grad_pc = mesh.gradient(pc_cells, pc_b);
    for (std::size_t c = 0; c < n; ++c)
      {
        s.u[c] -= D_simplec[c] * grad_pc[c].x();
        s.v[c] -= D_simplec[c] * grad_pc[c].y();
        cavitation.set_cell_pressure(s.p, c, s.p[c] + relaxation * pc[c]);
      }
    return sum;
  }
} // namespace servodrift::flow
