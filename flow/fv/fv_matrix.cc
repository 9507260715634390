#include "flow/fv/fv_matrix.h"

#include "common/error.h"
#include "flow/fv/gauss_seidel_preconditioner.h"
#include "flow/fv/limiter.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace servodrift::flow
{
  namespace
  {
    /// BiCGSTAB's iteration limit: the correction of one outer iteration needs tens at most
    constexpr int max_bicgstab_iterations = 1000;
    /// ILUT's drop tolerance and fill factor (Eigen's defaults are 1e-16 and 10)
    constexpr double ilut_drop_tolerance = 1e-4;
    constexpr int ilut_fill_factor = 10;
  } // namespace

  MatrixPattern::MatrixPattern(const FvMesh &mesh)
  {
    const std::size_t n = mesh.n_cells();
    std::vector<Eigen::Triplet<double>> t;
    for (std::size_t c = 0; c < n; ++c)
      t.emplace_back(c, c, 1.0);
    mesh.for_each_interior_face([&](std::size_t, unsigned int P, unsigned int N) {
      t.emplace_back(P, N, 0.0);
      t.emplace_back(N, P, 0.0);
    });
    matrix.resize(n, n);
    matrix.setFromTriplets(t.begin(), t.end());
    matrix.makeCompressed();
    auto position = [this](std::size_t r, std::size_t c) { // row r's column indices are sorted
      const int *inner = matrix.innerIndexPtr(), *outer = matrix.outerIndexPtr();
      return std::lower_bound(inner + outer[r], inner + outer[r + 1], static_cast<int>(c)) - inner;
    };
    diagonal.resize(n);
    for (std::size_t c = 0; c < n; ++c)
      diagonal[c] = position(c, c);
    owner_row.assign(mesh.n_faces(), -1);
    neighbour_row.assign(mesh.n_faces(), -1);
    mesh.for_each_interior_face([&](std::size_t f, unsigned int P, unsigned int N) {
      owner_row[f] = position(P, N);
      neighbour_row[f] = position(N, P);
    });
  }

  struct FvMatrix::IterativeSolvers
  {
    Eigen::BiCGSTAB<RowMajorMatrix, Eigen::IncompleteLUT<double>> ilu;
    Eigen::BiCGSTAB<RowMajorMatrix, Eigen::DiagonalPreconditioner<double>> jacobi;
    Eigen::BiCGSTAB<RowMajorMatrix, SymmetricGaussSeidelPreconditioner> gauss_seidel;
  };

  FvMatrix::FvMatrix(const FvMesh &mesh_, const MatrixPattern &pattern_)
    : A(pattern_.matrix)
    , pattern(pattern_)
    , mesh(mesh_)
    , solvers(std::make_unique<IterativeSolvers>())
  {}

  FvMatrix::~FvMatrix() = default;

  void FvMatrix::assemble_convection_diffusion(const std::vector<double> &phi, const std::vector<double> &phi_b,
                                               const std::vector<double> &gamma, const std::vector<double> &flux,
                                               const BoundaryConditions &boundaries,
                                               FlowSolverParameters::Convection convection)
  {
    using Kind = BoundaryCondition::Kind;
    const std::size_t n = mesh.n_cells();
    double *value = A.valuePtr();
    std::fill(value, value + A.nonZeros(), 0.0);
    b.setZero(n);
    diagonal.assign(n, 0.0);
    neighbour_sum.assign(n, 0.0);
    mesh.gradient(phi, phi_b, grad);
    const bool second_order = convection == FlowSolverParameters::Convection::bounded_linear_upwind;
    if (second_order && !(limiter_held && psi.size() == n))
      psi = barth_jespersen_limiter(mesh, phi, phi_b, grad);

    mesh.for_each_face(
      [&](std::size_t f, unsigned int P, unsigned int N) {
        const Vector2 &nrm = mesh.face_normal[f];
        const double area = mesh.face_area[f], F = flux[f];
        const Vector2 d = mesh.cell_center[N] - mesh.cell_center[P];
        // diffusion, over-relaxed split S = E + T with E along d: implicit gamma |E|/|d|, explicit T part
        const double Df = gamma[f] * area / nrm.dot(d);
        const double aPN = Df + std::max(-F, 0.0), aNP = Df + std::max(F, 0.0); // upwind convection
        value[pattern.owner_row[f]] = -aPN;
        value[pattern.neighbour_row[f]] = -aNP;
        diagonal[P] += aPN, diagonal[N] += aNP;
        neighbour_sum[P] += aPN, neighbour_sum[N] += aNP;
        const Vector2 grad_f = mesh.interpolate(f, grad);
        const Vector2 T = area * nrm - area / nrm.dot(d) * d;
        const double nonorthogonal = gamma[f] * grad_f.dot(T);
        b[P] += nonorthogonal, b[N] -= nonorthogonal;
        if (second_order)
          {
            // deferred correction: F (phi_face,linear upwind - phi_upwind) moves to the source
            const unsigned int U = F >= 0 ? P : N;
            const double correction = F * psi[U] * grad[U].dot(mesh.face_center[f] - mesh.cell_center[U]);
            b[P] -= correction, b[N] += correction;
          }
      },
      [&](std::size_t f, unsigned int P) {
        const double F = flux[f];
        double a = 0;
        switch (boundaries.kind(f))
          {
            case Kind::wall:
            case Kind::velocity_inlet:
              a = gamma[f] * mesh.face_area[f] / mesh.distance_to_face(f) + std::max(-F, 0.0);
              break;
            case Kind::pressure_outlet:
            case Kind::total_pressure_inlet:
              a = std::max(-F, 0.0); // inflow carries the boundary value in; outflow leaves with the cell's
              break;
            default: break; // axis (no area), symmetry (no flux; the momentum adds its own)
          }
        diagonal[P] += a;
        b[P] += a * phi_b[f];
      });
  }

  double FvMatrix::relax(const std::vector<double> &phi, double alpha, const std::vector<double> &scale_field,
                         double &scale)
  {
    const std::size_t n = mesh.n_cells();
    double *value = A.valuePtr();
    for (std::size_t c = 0; c < n; ++c)
      value[pattern.diagonal[c]] = diagonal[c];
    Eigen::Map<const Eigen::VectorXd> x(phi.data(), n);
    const Eigen::VectorXd r = b - A * x;
    double residual = 0;
    scale = 0;
    for (std::size_t c = 0; c < n; ++c)
      {
        residual += std::abs(r[c]);
        scale += diagonal[c] * std::abs(scale_field[c]);
      }
    for (std::size_t c = 0; c < n; ++c)
      {
        value[pattern.diagonal[c]] = diagonal[c] / alpha;
        b[c] += (1 - alpha) / alpha * diagonal[c] * phi[c];
      }
    return residual;
  }

  void FvMatrix::solve(std::vector<double> &phi, const FlowSolverParameters &settings,
                       FlowSolverParameters::MomentumSolver preconditioner, const char *equation)
  {
    Eigen::Map<Eigen::VectorXd> x(phi.data(), mesh.n_cells());
    const Eigen::VectorXd r = b - A * x;
    if (r.norm() == 0)
      return;
    auto run = [&](auto &solver) {
      solver.setTolerance(settings.linear_solver_tolerance);
      solver.setMaxIterations(max_bicgstab_iterations);
      solver.compute(A);
      const Eigen::VectorXd dx = solver.solve(r);
      if (solver.info() != Eigen::Success)
        throw std::runtime_error(std::string("BiCGSTAB did not converge on the ") + equation + " equation (" +
                                 std::to_string(solver.iterations()) + " iterations, relative residual " +
                                 format_number(solver.error()) + ")");
      x += dx;
    };
    switch (preconditioner)
      {
        case FlowSolverParameters::MomentumSolver::bicgstab_ilu:
          solvers->ilu.preconditioner().setDroptol(ilut_drop_tolerance);
          solvers->ilu.preconditioner().setFillfactor(ilut_fill_factor);
          run(solvers->ilu);
          break;
        case FlowSolverParameters::MomentumSolver::bicgstab_gauss_seidel: run(solvers->gauss_seidel); break;
        default: run(solvers->jacobi); // also where the caller has a direct solver of its own
      }
  }
} // namespace servodrift::flow
