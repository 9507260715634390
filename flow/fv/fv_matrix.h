#pragma once
// The matrix of one transport equation on the finite-volume mesh (OpenFOAM's fvMatrix, in small):
// a_P phi_P - sum_nb a_nb phi_nb = b per cell, on a sparse pattern built once per mesh (the diagonal
// and both sides of every interior face), its values written in place at every assembly
// (architecture.md example 5). Convection-diffusion terms, under-relaxation and the iterative solve
// are here; each equation (momentum, k, epsilon) adds its own sources and sinks.
#include "common/parameters/flow_solver.h"
#include "flow/fv/boundary_conditions.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>
#include <vector>

namespace servodrift::flow
{
  using SparseMatrix = Eigen::SparseMatrix<double>;
  /// The transport equations' matrices are stored by rows: BiCGSTAB's products A x then gather
  /// along a row instead of scattering down a column, which is most of its cost.
  using RowMajorMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

  /// The pattern of a cell-by-cell matrix, and where each coefficient sits in its value array.
  /// The pattern is structurally symmetric (both sides of every face), so a column-major copy of
  /// `matrix' has the same index arrays, and the positions below serve a matrix with symmetric
  /// values (the pressure equation's) in either storage.
  struct MatrixPattern
  {
    explicit MatrixPattern(const FvMesh &mesh);
    RowMajorMatrix matrix;                         ///< compressed, row-major, values zero
    std::vector<std::ptrdiff_t> diagonal;          ///< per cell: entry (c, c)
    std::vector<std::ptrdiff_t> owner_row;         ///< per interior face: entry (owner, neighbour); -1 on the boundary
    std::vector<std::ptrdiff_t> neighbour_row;     ///< per interior face: entry (neighbour, owner)
  };

  class FvMatrix
  {
  public:
    FvMatrix(const FvMesh &mesh, const MatrixPattern &pattern);
    ~FvMatrix();

    /// Convection (upwind implicitly; with the bounded linear upwind scheme its second-order part
    /// as a deferred correction: F psi_U grad(phi)_U . (x_f - x_U) moved to b) and diffusion
    /// (central gamma |S|/(n.d) (phi_N - phi_P) implicitly, the non-orthogonal part gamma grad(phi)_f
    /// . T explicitly) of phi with the face fluxes F and face diffusivities gamma. The off-diagonal
    /// values go into A, the diagonal into `diagonal' (not yet into A: relax() writes it), sum a_nb
    /// into `neighbour_sum', the sources into b. Boundary faces: walls and velocity inlets hold
    /// phi_b (diffusion and inflow); at a pressure boundary an inflow carries phi_b in; axis and
    /// symmetry add nothing here.
    void assemble_convection_diffusion(const std::vector<double> &phi, const std::vector<double> &phi_b,
                                       const std::vector<double> &gamma, const std::vector<double> &flux,
                                       const BoundaryConditions &boundaries,
                                       FlowSolverParameters::Convection convection);
    /// Holds the bounded scheme's limiter at the values of the last assembly (a frozen limiter, as
    /// SU2's LIMITER_ITER and FUN3D's freeze_limiter_iteration): Barth-Jespersen's min is not
    /// differentiable, and where it switches between faces from one iteration to the next the
    /// residual hovers instead of converging (doc/method.md, "Cycles and stalls").
    void hold_limiter(bool hold) { limiter_held = hold; }
    /// Under-relaxation by alpha (Patankar): the diagonal a_P/alpha into A and (1 - alpha)/alpha a_P
    /// phi into b. Returns sum |b - A phi| of the unrelaxed equation at the current phi, and in `scale'
    /// sum a_P |scale_field|, what that residual is relative to.
    double relax(const std::vector<double> &phi, double alpha, const std::vector<double> &scale_field, double &scale);
    /// BiCGSTAB with `preconditioner' (`Flow solver/Momentum solver' or `Turbulence solver';
    /// Jacobi for the direct solver) on the correction, so that its tolerance is relative to the
    /// current residual; `equation' names it in the error thrown if it does not converge.
    void solve(std::vector<double> &phi, const FlowSolverParameters &settings,
               FlowSolverParameters::MomentumSolver preconditioner, const char *equation);

    RowMajorMatrix A;                   ///< the coefficients, on the pattern
    Eigen::VectorXd b;                  ///< the right-hand side
    std::vector<double> diagonal;       ///< a_P before relaxation
    std::vector<double> neighbour_sum;  ///< sum of the a_nb of each row
    const MatrixPattern &pattern;

  private:
    const FvMesh &mesh;
    std::vector<Vector2> grad;   ///< work: the gradient of the transported field
    std::vector<double> psi;     ///< the limiter of the last assembly (bounded scheme)
    bool limiter_held = false;
    struct IterativeSolvers;
    std::unique_ptr<IterativeSolvers> solvers;
  };
} // namespace servodrift::flow
