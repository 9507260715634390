#pragma once
// MagnetostaticProblem's implementation: the state that the units of the planar magnetostatic solver
// share. Private to magnetostatic_problem.cc (set-up, assembly and Newton solve of the A_z equation,
// model.md 4.1), mesh_morphing.cc (the body's motion and the extension of it into the air) and
// magnetostatic_fields.cc (what is computed from a solution: forces, coenergy, flux densities, VTU).
#include "magnetics/magnetostatic_problem.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>

#include <map>
#include <string>
#include <vector>

namespace servodrift::magnetics
{
  using namespace dealii;

  namespace detail
  {
    using EigenMatrix = Eigen::SparseMatrix<double>;
    // CHOLMOD's supernodal LL^T. Its OpenMP teams (a compiled-in 4 threads) would only compete with
    // the MPI ranks that share out the sweeps; each main keeps them to one thread (common/sweep.h).
    using Cholesky = Eigen::CholmodSupernodalLLT<EigenMatrix, Eigen::Lower>;

    /// B = curl(A e_z) = (dA/dy, -dA/dx) in the plane
    inline Tensor<1, 2> flux_density(const Tensor<1, 2> &grad_A)
    {
      Tensor<1, 2> B;
      B[0] = grad_A[1];
      B[1] = -grad_A[0];
      return B;
    }

    inline void check(const Cholesky &solver, const char *what)
    {
      if (solver.info() != Eigen::Success)
        throw std::runtime_error(std::string("magnetostatics: CHOLMOD failed in ") + what +
                                 " (matrix not positive definite?)");
    }
  } // namespace detail

  struct MagnetostaticProblem::Implementation
  {
    using EigenMatrix = detail::EigenMatrix;
    using Cholesky = detail::Cholesky;

    std::map<int, Material> materials;
    Motion motion;
    double depth;
    double s = 0;       ///< current position
    double current = 0; ///< current excitation of the last solve
    double tolerance = 1e-10; ///< of the last solve

    Triangulation<2> triangulation;
    std::vector<Point<2>> reference_vertices;

    // A_z
    FE_Q<2> fe;
    DoFHandler<2> dof_handler;
    QGauss<2> quadrature;
    AffineConstraints<double> constraints; ///< A_z = 0 on the outer boundary (homogeneous)
    SparsityPattern sparsity;
    SparseMatrix<double> jacobian;
    Vector<double> solution, rhs;
    EigenMatrix eigen_jacobian;
    std::vector<std::ptrdiff_t> eigen_position; ///< deal.II storage index -> Eigen value index
    Cholesky cholesky;
    bool have_factorization = false;       ///< a numeric factorisation of a recent Jacobian exists
    /// DoF indices and material of every cell: fixed by the topology, which morphing keeps.
    std::vector<types::global_dof_index> cell_dofs; ///< [cell * dofs_per_cell + i]
    std::vector<const Material *> cell_material;    ///< [cell], into `materials'
    /// Geometry of every cell at one position: the assembly loops of the Newton and chord iterations
    /// are pure arithmetic on it. Flat arrays, so that virtual work keeps a position's geometry by a
    /// swap, without allocations.
    struct CellGeometry
    {
      std::vector<double> JxW;                   ///< [cell * n_q + q]
      std::vector<Tensor<1, 2>> shape_gradients; ///< [(cell * n_q + q) * dofs_per_cell + i]
    };
    CellGeometry cell_geometry;       ///< at the current position
    CellGeometry kept_cell_geometry;  ///< virtual work: the position's own, while it solves beside it
    FullMatrix<double> shape_values; ///< [q][i] on the reference cell
    void update_cell_geometry();
    std::map<double, double> source_norm;  ///< ||R(A = 0)|| per current: the scale of the tolerance
    /// The solution's derivatives in the position at one position and current, dA/ds and d2A/ds2,
    /// from virtual work's central differences or, without it, from the last three solves at that
    /// current (their interpolating parabola): a solve at another position and the same current
    /// starts from the second-order prediction A + ds dA/ds + ds^2/2 d2A/ds2 instead of A
    /// (MagnetostaticProblem::solve).
    struct Tangent
    {
      bool known = false;
      double position = 0, current = 0;
      Vector<double> A, dA_ds, d2A_ds2;
    } tangent;
    /// The last solves at the case's own position (not virtual work's beside it), newest last: at
    /// most three, all at one current.
    struct Solved
    {
      double position, current;
      Vector<double> A;
    };
    std::vector<Solved> solved;
    /// Records the solve just done and, from the solves at this current, the tangent by divided
    /// differences: the secant through two, the parabola through three.
    void remember_solve();

    // morphing: vertex displacement (Q1) extended into the morphing air by a Laplace solve
    FE_Q<2> fe_morph;
    DoFHandler<2> morph_dof_handler;
    std::vector<unsigned int> vertex_of_dof;
    std::vector<int> free_index, fixed_index; ///< per morph DoF; -1 where not in that set
    std::vector<bool> moving_dof;
    EigenMatrix K_ff, K_fd;
    Cholesky morph_cholesky;
    Eigen::MatrixXd extended_motion_fields;  ///< F1, F2 extended into the morphing air (motion_fields)
    std::array<Vector<double>, 2> velocity; ///< virtual velocity of the body, extended (for the MST)

    Implementation(const PlanarMesh &mesh, const std::map<int, Material> &materials, const Motion &motion,
                   unsigned int degree, double depth, unsigned int refinements);

    const Material &material(const DoFHandler<2>::active_cell_iterator &cell) const
    {
      return materials.at(static_cast<int>(cell->material_id()));
    }

    void setup_system();
    void setup_morphing();
    /// The two fields F1, F2 on the body's DoFs (columns x, y of each; zero elsewhere) whose
    /// combinations are the motion's displacement and virtual velocity at every position.
    Eigen::MatrixXd motion_fields() const;
    /// (a_u, b_u, a_w, b_w) of displacement u = a_u F1 + b_u F2 and velocity w = a_w F1 + b_w F2.
    std::array<double, 4> motion_coefficients(double position) const;
    /// The Laplace extension of fields given at the fixed DoFs (columns of `boundary', rows the
    /// morph DoFs; its free rows are ignored) into the morphing air: one solve for every column.
    Eigen::MatrixXd extend(const Eigen::MatrixXd &boundary) const;
    void move_to(double position);

    void assemble_system(const Vector<double> &A, bool with_matrix);
    double residual_norm(const Vector<double> &A);
    NewtonStatistics solve(double current, double tolerance, unsigned int max_iterations);
    void solve_linear_system(Vector<double> &update);
  };
} // namespace servodrift::magnetics
