#include "magnetics/magnetostatic_problem.h"

#include "common/output_files.h"
#include "common/units.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>
#include <deal.II/numerics/vector_tools.h>

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>

#include <algorithm>

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace servodrift::magnetics
{
  using namespace dealii;
  using units::mu0;

  namespace
  {
    using EigenMatrix = Eigen::SparseMatrix<double>;
    // CHOLMOD's simplicial LDL^T: its supernodal variant runs OpenMP teams of a compiled-in 4 threads
    // (CHOLMOD_OMP_NUM_THREADS), which only compete with the MPI ranks that share out the sweeps.
    using Cholesky = Eigen::CholmodSupernodalLLT<EigenMatrix, Eigen::Lower>;

    /// B = curl(A e_z) = (dA/dy, -dA/dx) in the plane
    Tensor<1, 2> flux_density(const Tensor<1, 2> &grad_A)
    {
      Tensor<1, 2> B;
      B[0] = grad_A[1];
      B[1] = -grad_A[0];
      return B;
    }

    void check(const Cholesky &solver, const char *what)
    {
      if (solver.info() != Eigen::Success)
        throw std::runtime_error(std::string("magnetostatics: CHOLMOD failed in ") + what +
                                 " (matrix not positive definite?)");
    }
  } // namespace

  struct MagnetostaticProblem::Implementation
  {
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
    /// Geometry of every cell at the current position (JxW, shape gradients, DoF indices): the
    /// assembly loops of the Newton and chord iterations are pure arithmetic on it.
    struct CellGeometry
    {
      std::vector<double> JxW;                  ///< [q]
      std::vector<Tensor<1, 2>> shape_gradients; ///< [q * dofs_per_cell + i]
      std::vector<types::global_dof_index> dofs;
      int material;
    };
    std::vector<CellGeometry> cell_geometry;
    FullMatrix<double> shape_values; ///< [q][i] on the reference cell
    void update_cell_geometry();
    std::map<double, double> source_norm;  ///< ||R(A = 0)|| per current: the scale of the tolerance

    // morphing: vertex displacement (Q1) extended into the morphing air by a Laplace solve
    FE_Q<2> fe_morph;
    DoFHandler<2> morph_dof_handler;
    std::vector<unsigned int> vertex_of_dof;
    std::vector<int> free_index, fixed_index; ///< per morph DoF; -1 where not in that set
    std::vector<bool> moving_dof;
    EigenMatrix K_ff, K_fd;
    Cholesky morph_cholesky;
    std::array<Vector<double>, 2> velocity; ///< virtual velocity of the body, extended (for the MST)

    Implementation(const PlanarMesh &mesh, const std::map<int, Material> &materials, const Motion &motion,
                   unsigned int degree, double depth, unsigned int refinements);

    const Material &material(const DoFHandler<2>::active_cell_iterator &cell) const
    {
      return materials.at(static_cast<int>(cell->material_id()));
    }

    void setup_system();
    void setup_morphing();
    std::array<double, 2> body_displacement(const Point<2> &x, double position) const;
    std::array<double, 2> body_velocity(const Point<2> &x_now) const;
    void extend(const std::array<Vector<double>, 2> &boundary_values, std::array<Vector<double>, 2> &field) const;
    void move_to(double position);

    void assemble_system(const Vector<double> &A, bool with_matrix);
    double residual_norm(const Vector<double> &A);
    NewtonStatistics solve(double current, double tolerance, unsigned int max_iterations);
    void solve_linear_system(Vector<double> &update);
  };

  MagnetostaticProblem::Implementation::Implementation(const PlanarMesh &mesh, const std::map<int, Material> &materials_,
                                                       const Motion &motion_, unsigned int degree, double depth_,
                                                       unsigned int refinements)
    : materials(materials_)
    , motion(motion_)
    , depth(depth_)
    , fe(degree)
    , dof_handler(triangulation)
    , quadrature(degree + 1)
    , fe_morph(1)
    , morph_dof_handler(triangulation)
  {
    if (degree < 1 || degree > 2)
      throw std::invalid_argument("magnetostatics: element degree must be 1 or 2");
    std::vector<Point<2>> vertices;
    for (const auto &v : mesh.vertices)
      vertices.emplace_back(v[0], v[1]);
    std::vector<CellData<2>> cells(mesh.cells.size());
    for (std::size_t c = 0; c < mesh.cells.size(); ++c)
      {
        const auto &v = mesh.cells[c].vertices; // counterclockwise -> deal.II's lexicographic order
        cells[c].vertices = {v[0], v[1], v[3], v[2]};
        if (materials.find(mesh.cells[c].material) == materials.end())
          throw std::logic_error("magnetostatics: no material for id " + std::to_string(mesh.cells[c].material));
        cells[c].material_id = static_cast<types::material_id>(mesh.cells[c].material);
      }
    SubCellData faces;
    for (const auto &f : mesh.boundary_faces)
      {
        CellData<1> line;
        line.vertices = {f.vertices[0], f.vertices[1]};
        line.boundary_id = static_cast<types::boundary_id>(f.boundary);
        faces.boundary_lines.push_back(line);
      }
    GridTools::consistently_order_cells(cells);
    triangulation.create_triangulation(vertices, cells, faces);
    triangulation.refine_global(refinements);
    reference_vertices = triangulation.get_vertices();
    setup_system();
    setup_morphing();
  }

  void MagnetostaticProblem::Implementation::setup_system()
  {
    dof_handler.distribute_dofs(fe);
    constraints.clear();
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    VectorTools::interpolate_boundary_values(dof_handler, types::boundary_id(1), Functions::ZeroFunction<2>(), constraints);
    constraints.close();
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, /*keep_constrained_dofs=*/true);
    sparsity.copy_from(dsp);
    jacobian.reinit(sparsity);
    solution.reinit(dof_handler.n_dofs());
    rhs.reinit(dof_handler.n_dofs());

    // The Eigen (CHOLMOD) matrix gets the same pattern once; afterwards only values are copied.
    const auto n = static_cast<Eigen::Index>(dof_handler.n_dofs());
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(sparsity.n_nonzero_elements());
    for (auto it = sparsity.begin(); it != sparsity.end(); ++it)
      triplets.emplace_back(it->row(), it->column(), 0.0);
    eigen_jacobian.resize(n, n);
    eigen_jacobian.setFromTriplets(triplets.begin(), triplets.end());
    eigen_jacobian.makeCompressed();
    eigen_position.clear();
    const int *outer = eigen_jacobian.outerIndexPtr();
    const int *inner = eigen_jacobian.innerIndexPtr();
    for (auto it = sparsity.begin(); it != sparsity.end(); ++it)
      {
        const auto c = it->column(), r = it->row();
        const int *p = std::lower_bound(inner + outer[c], inner + outer[c + 1], static_cast<int>(r));
        eigen_position.push_back(p - inner);
      }
    cholesky.analyzePattern(eigen_jacobian); // symbolic factorisation: once per mesh
    check(cholesky, "the symbolic analysis");
  }

  void MagnetostaticProblem::Implementation::setup_morphing()
  {
    morph_dof_handler.distribute_dofs(fe_morph);
    const unsigned int n = morph_dof_handler.n_dofs();
    vertex_of_dof.assign(n, 0);
    std::vector<bool> fixed(n, false), moving(n, false), in_body(n, false);
    for (const auto &cell : morph_dof_handler.active_cell_iterators())
      {
        const Material &m = material(cell);
        for (unsigned int v = 0; v < 4; ++v)
          {
            const auto d = cell->vertex_dof_index(v, 0);
            vertex_of_dof[d] = cell->vertex_index(v);
            if (!m.morphing)
              fixed[d] = true;
            if (m.moving)
              moving[d] = true;
            else if (!m.morphing)
              in_body[d] = true; // a solid that stays
          }
        for (unsigned int f = 0; f < 4; ++f)
          if (cell->face(f)->at_boundary())
            for (unsigned int v = 0; v < 2; ++v)
              fixed[cell->face(f)->vertex_dof_index(v, 0)] = true;
      }
    for (unsigned int d = 0; d < n; ++d)
      if (moving[d] && in_body[d])
        throw std::logic_error("magnetostatics: the moving body touches a fixed solid; put air between them");
    moving_dof = moving;

    free_index.assign(n, -1);
    fixed_index.assign(n, -1);
    int n_free = 0, n_fixed = 0;
    for (unsigned int d = 0; d < n; ++d)
      (fixed[d] ? fixed_index[d] = n_fixed++ : free_index[d] = n_free++);

    // Laplace operator on the morphing air, reference configuration: assembled and factorised once
    FEValues<2> fe_values(fe_morph, QGauss<2>(2), update_gradients | update_JxW_values);
    std::vector<types::global_dof_index> dofs(4);
    std::vector<Eigen::Triplet<double>> t_ff, t_fd;
    for (const auto &cell : morph_dof_handler.active_cell_iterators())
      {
        if (!material(cell).morphing)
          continue;
        fe_values.reinit(cell);
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < 4; ++i)
          {
            if (free_index[dofs[i]] < 0)
              continue;
            for (unsigned int j = 0; j < 4; ++j)
              {
                double k = 0;
                for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
                  k += fe_values.shape_grad(i, q) * fe_values.shape_grad(j, q) * fe_values.JxW(q);
                if (free_index[dofs[j]] >= 0)
                  t_ff.emplace_back(free_index[dofs[i]], free_index[dofs[j]], k);
                else
                  t_fd.emplace_back(free_index[dofs[i]], fixed_index[dofs[j]], k);
              }
          }
      }
    K_ff.resize(n_free, n_free);
    K_ff.setFromTriplets(t_ff.begin(), t_ff.end());
    K_fd.resize(n_free, n_fixed);
    K_fd.setFromTriplets(t_fd.begin(), t_fd.end());
    if (n_free > 0)
      {
        morph_cholesky.compute(K_ff);
        check(morph_cholesky, "the mesh-morphing factorisation");
      }
    for (auto &v : velocity)
      v.reinit(n);
    move_to(0.0);
  }

  std::array<double, 2> MagnetostaticProblem::Implementation::body_displacement(const Point<2> &x, double position) const
  {
    if (motion.kind == Motion::Kind::translation)
      return {position * motion.direction[0], position * motion.direction[1]};
    const double c = std::cos(position), sn = std::sin(position);
    const double dx = x[0] - motion.point[0], dy = x[1] - motion.point[1];
    return {motion.point[0] + c * dx - sn * dy - x[0], motion.point[1] + sn * dx + c * dy - x[1]};
  }

  std::array<double, 2> MagnetostaticProblem::Implementation::body_velocity(const Point<2> &x_now) const
  {
    if (motion.kind == Motion::Kind::translation)
      return motion.direction;
    return {-(x_now[1] - motion.point[1]), x_now[0] - motion.point[0]}; // e_z x (x - pivot)
  }

  void MagnetostaticProblem::Implementation::extend(const std::array<Vector<double>, 2> &boundary,
                                                    std::array<Vector<double>, 2> &field) const
  {
    // u_F = -K_ff^-1 K_fd u_D on each component
    const unsigned int n = morph_dof_handler.n_dofs();
    for (unsigned int k = 0; k < 2; ++k)
      {
        field[k].reinit(n);
        Eigen::VectorXd u_D(K_fd.cols());
        for (unsigned int d = 0; d < n; ++d)
          if (fixed_index[d] >= 0)
            {
              u_D[fixed_index[d]] = boundary[k][d];
              field[k][d] = boundary[k][d];
            }
        if (K_ff.rows() == 0)
          continue;
        const Eigen::VectorXd rhs_free = -(K_fd * u_D);
        const Eigen::VectorXd u_F = morph_cholesky.solve(rhs_free);
        check(morph_cholesky, "the mesh-morphing solve");
        for (unsigned int d = 0; d < n; ++d)
          if (free_index[d] >= 0)
            field[k][d] = u_F[free_index[d]];
      }
  }

  void MagnetostaticProblem::Implementation::move_to(double position)
  {
    const unsigned int n = morph_dof_handler.n_dofs();
    std::array<Vector<double>, 2> boundary{Vector<double>(n), Vector<double>(n)}, displacement;
    for (unsigned int d = 0; d < n; ++d)
      if (moving_dof[d])
        {
          const auto u = body_displacement(reference_vertices[vertex_of_dof[d]], position);
          boundary[0][d] = u[0];
          boundary[1][d] = u[1];
        }
    extend(boundary, displacement);

    std::vector<Point<2>> moved(reference_vertices.size());
    for (unsigned int d = 0; d < n; ++d)
      {
        const unsigned int v = vertex_of_dof[d];
        moved[v] = reference_vertices[v] + Point<2>(displacement[0][d], displacement[1][d]);
      }
    // A morphed cell must stay convex and counterclockwise: cross products at its four corners
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        static const unsigned int ring[4] = {0, 1, 3, 2}; // counterclockwise in deal.II's numbering
        for (unsigned int k = 0; k < 4; ++k)
          {
            const Point<2> &p = moved[cell->vertex_index(ring[k])], &a = moved[cell->vertex_index(ring[(k + 1) % 4])],
                           &b = moved[cell->vertex_index(ring[(k + 3) % 4])];
            const double cross = (a[0] - p[0]) * (b[1] - p[1]) - (a[1] - p[1]) * (b[0] - p[0]);
            if (!(cross > 0))
              throw std::runtime_error("mesh morphing: the motion to " + std::to_string(position) +
                                       " inverts a cell of the air around the moving body (the motion is "
                                       "too large for the gap)");
          }
      }
    for (const auto &cell : triangulation.active_cell_iterators())
      for (unsigned int v = 0; v < 4; ++v)
        cell->vertex(v) = moved[cell->vertex_index(v)];
    s = position;
    update_cell_geometry();

    // virtual velocity of the body at its current position, extended into the air (for the MST)
    for (unsigned int d = 0; d < n; ++d)
      if (moving_dof[d])
        {
          const auto w = body_velocity(moved[vertex_of_dof[d]]);
          boundary[0][d] = w[0];
          boundary[1][d] = w[1];
        }
      else
        boundary[0][d] = boundary[1][d] = 0;
    extend(boundary, velocity);
  }

  void MagnetostaticProblem::Implementation::update_cell_geometry()
  {
    FEValues<2> fe_values(fe, quadrature, update_gradients | update_JxW_values);
    const unsigned int dofs_per_cell = fe.n_dofs_per_cell(), n_q = quadrature.size();
    cell_geometry.resize(triangulation.n_active_cells());
    shape_values.reinit(n_q, dofs_per_cell);
    for (unsigned int q = 0; q < n_q; ++q)
      for (unsigned int i = 0; i < dofs_per_cell; ++i)
        shape_values(q, i) = fe.shape_value(i, quadrature.point(q));
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        CellGeometry &g = cell_geometry[cell->active_cell_index()];
        fe_values.reinit(cell);
        g.JxW.resize(n_q);
        g.shape_gradients.resize(n_q * dofs_per_cell);
        g.dofs.resize(dofs_per_cell);
        cell->get_dof_indices(g.dofs);
        g.material = static_cast<int>(cell->material_id());
        for (unsigned int q = 0; q < n_q; ++q)
          {
            g.JxW[q] = fe_values.JxW(q);
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              g.shape_gradients[q * dofs_per_cell + i] = fe_values.shape_grad(i, q);
          }
      }
  }

  void MagnetostaticProblem::Implementation::assemble_system(const Vector<double> &A, bool with_matrix)
  {
    if (with_matrix)
      jacobian = 0;
    rhs = 0;
    const unsigned int dofs_per_cell = fe.n_dofs_per_cell(), n_q = quadrature.size();
    FullMatrix<double> cell_matrix(dofs_per_cell, dofs_per_cell);
    Vector<double> cell_rhs(dofs_per_cell);
    std::vector<double> A_local(dofs_per_cell);
    for (const CellGeometry &g : cell_geometry)
      {
        const Material &m = materials.at(g.material);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          A_local[i] = A[g.dofs[i]];
        cell_matrix = 0;
        cell_rhs = 0;
        const double J = m.current_density * current;
        const double Brx = m.remanence[0], Bry = m.remanence[1]; // magnet: H = nu_m (B - B_r)
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const double JxW = g.JxW[q];
            const Tensor<1, 2> *grad = &g.shape_gradients[q * dofs_per_cell];
            Tensor<1, 2> grad_A;
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              grad_A += A_local[i] * grad[i];
            double nu = 1 / (mu0 * m.relative_permeability), nu_extra = 0; // air, linear iron, magnet
            if (m.kind == Material::Kind::nonlinear)
              {
                // H = nu(|B|) B: Jacobian nu I + (nu_d - nu) B (x) B/|B|^2 (nu_d = dH/dB)
                const double b2 = grad_A * grad_A;
                double nu_d;
                m.curve->reluctivities(std::sqrt(b2), nu, nu_d);
                if (b2 > 0)
                  nu_extra = (nu_d - nu) / b2;
              }
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              {
                const Tensor<1, 2> &gi = grad[i];
                const double g_gi = grad_A * gi;
                // R_i = int nu grad A . grad phi_i - nu B_r . curl phi_i - J phi_i (-div(nu grad A) = J),
                // with B_r . curl phi = B_r,x dphi/dy - B_r,y dphi/dx
                const double R_i = nu * g_gi - nu * (Brx * gi[1] - Bry * gi[0]) - J * shape_values(q, i);
                cell_rhs(i) -= R_i * JxW;
                if (with_matrix)
                  for (unsigned int j = 0; j < dofs_per_cell; ++j)
                    cell_matrix(i, j) += (nu * (gi * grad[j]) + nu_extra * g_gi * (grad_A * grad[j])) * JxW;
              }
          }
        if (with_matrix)
          constraints.distribute_local_to_global(cell_matrix, cell_rhs, g.dofs, jacobian, rhs);
        else
          constraints.distribute_local_to_global(cell_rhs, g.dofs, rhs);
      }
  }

  double MagnetostaticProblem::Implementation::residual_norm(const Vector<double> &A)
  {
    assemble_system(A, false);
    return rhs.l2_norm();
  }

  void MagnetostaticProblem::Implementation::solve_linear_system(Vector<double> &update)
  {
    double *values = eigen_jacobian.valuePtr();
    std::size_t k = 0;
    for (auto it = jacobian.begin(); it != jacobian.end(); ++it, ++k)
      values[eigen_position[k]] = it->value();
    cholesky.factorize(eigen_jacobian); // numeric factorisation; the symbolic one is reused
    check(cholesky, "the factorisation of the Newton matrix");
    Eigen::Map<const Eigen::VectorXd> b(rhs.begin(), rhs.size());
    const Eigen::VectorXd x = cholesky.solve(b);
    check(cholesky, "the Newton solve");
    update.reinit(rhs.size());
    std::copy(x.data(), x.data() + x.size(), update.begin());
    constraints.distribute(update);
  }

  NewtonStatistics MagnetostaticProblem::Implementation::solve(double current_, double tolerance, unsigned int max_iterations)
  {
    current = current_;
    this->tolerance = tolerance;
    NewtonStatistics stats;
    Vector<double> update, trial;
    auto cached = source_norm.find(current);
    if (cached == source_norm.end())
      cached = source_norm.emplace(current, residual_norm(Vector<double>(dof_handler.n_dofs()))).first;
    stats.initial_residual = cached->second;
    if (stats.initial_residual == 0)
      {
        solution = 0;
        return stats;
      }
    constraints.set_zero(solution);
    const double target = tolerance * stats.initial_residual;
    double r = residual_norm(solution);

    // Chord iterations first: the factorisation of the last Jacobian (previous angle or current, often
    // the same mesh position) is reused while it still contracts the residual at least tenfold per
    // step; otherwise Newton takes over, with a fresh Jacobian every iteration.
    while (r > target && have_factorization && stats.iterations < max_iterations)
      {
        Vector<double> step(rhs.size());
        {
          Eigen::Map<const Eigen::VectorXd> b(rhs.begin(), rhs.size());
          const Eigen::VectorXd x = cholesky.solve(b);
          check(cholesky, "a chord step");
          std::copy(x.data(), x.data() + x.size(), step.begin());
        }
        constraints.distribute(step);
        trial = solution;
        trial += step;
        const double r_trial = residual_norm(trial);
        ++stats.iterations;
        if (!(r_trial < 0.1 * r))
          {
            residual_norm(solution); // restore rhs at the accepted iterate
            break;
          }
        solution = trial;
        r = r_trial;
      }

    // Newton with backtracking line search on the residual norm (Armijo)
    if (r > target)
      assemble_system(solution, true);
    while (r > target)
      {
        if (stats.iterations >= max_iterations)
          throw std::runtime_error("magnetostatics: Newton did not converge in " + std::to_string(max_iterations) +
                                   " iterations (residual " + std::to_string(r / stats.initial_residual) +
                                   " of the initial one)");
        solve_linear_system(update);
        have_factorization = true;
        ++stats.iterations;
        double alpha = 1, r_trial = 0;
        for (int halvings = 0;; ++halvings)
          {
            trial = solution;
            trial.add(alpha, update);
            r_trial = residual_norm(trial);
            if (r_trial <= (1 - 1e-4 * alpha) * r || halvings == 30)
              break;
            alpha /= 2;
          }
        if (!(r_trial < r))
          throw std::runtime_error("magnetostatics: the Newton line search found no decrease of the residual");
        solution = trial;
        r = r_trial;
        if (r > target)
          assemble_system(solution, true);
      }
    stats.final_residual = r;
    return stats;
  }

  // ---- public interface ----------------------------------------------------------------------

  MagnetostaticProblem::MagnetostaticProblem(const PlanarMesh &mesh, const std::map<int, Material> &materials,
                                             const Motion &motion, unsigned int fe_degree, double depth,
                                             unsigned int global_refinements)
    : impl(std::make_unique<Implementation>(mesh, materials, motion, fe_degree, depth, global_refinements))
  {}

  MagnetostaticProblem::~MagnetostaticProblem() = default;

  void MagnetostaticProblem::set_position(double s)
  {
    impl->move_to(s);
  }

  double MagnetostaticProblem::position() const
  {
    return impl->s;
  }

  NewtonStatistics MagnetostaticProblem::solve(double current, double tolerance, unsigned int max_iterations)
  {
    return impl->solve(current, tolerance, max_iterations);
  }

  double MagnetostaticProblem::stress_tensor_force() const
  {
    // F = -w_d int_air T_M : grad V dA, T_M = nu0 (B (x) B - |B|^2/2 I), over the morphing air where V
    // goes from the body's velocity to zero (4.1 item 2)
    const auto &d = *impl;
    const double nu0 = 1 / mu0;
    FEValues<2> fe_values(d.fe, d.quadrature, update_gradients | update_JxW_values);
    FEValues<2> morph_values(d.fe_morph, d.quadrature, update_gradients);
    const unsigned int n_q = d.quadrature.size();
    std::vector<Tensor<1, 2>> grad_A(n_q), grad_Vx(n_q), grad_Vy(n_q);
    double integral = 0;
    auto morph_cell = d.morph_dof_handler.begin_active();
    for (auto cell = d.dof_handler.begin_active(); cell != d.dof_handler.end(); ++cell, ++morph_cell)
      {
        if (!d.material(cell).morphing)
          continue;
        fe_values.reinit(cell);
        morph_values.reinit(morph_cell);
        fe_values.get_function_gradients(d.solution, grad_A);
        morph_values.get_function_gradients(d.velocity[0], grad_Vx);
        morph_values.get_function_gradients(d.velocity[1], grad_Vy);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const Tensor<1, 2> B = flux_density(grad_A[q]);
            const double b2 = B * B;
            const double div_V = grad_Vx[q][0] + grad_Vy[q][1];
            const double BgradVB = B[0] * (B * grad_Vx[q]) + B[1] * (B * grad_Vy[q]);
            integral += nu0 * (BgradVB - 0.5 * b2 * div_V) * fe_values.JxW(q);
          }
      }
    return -d.depth * integral;
  }

  double MagnetostaticProblem::coenergy() const
  {
    const auto &d = *impl;
    const unsigned int dofs_per_cell = d.fe.n_dofs_per_cell(), n_q = d.quadrature.size();
    double W = 0;
    for (const auto &g : d.cell_geometry)
      {
        const Material &m = d.materials.at(g.material);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            Tensor<1, 2> grad_A;
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              grad_A += d.solution[g.dofs[i]] * g.shape_gradients[q * dofs_per_cell + i];
            const Tensor<1, 2> B = flux_density(grad_A);
            const double b2 = B * B;
            double w = 0; // coenergy density w' = int_0^H B dH'
            switch (m.kind)
              {
                case Material::Kind::air:
                case Material::Kind::linear:
                  w = 0.5 * b2 / (mu0 * m.relative_permeability); // B^2/(2 mu)
                  break;
                case Material::Kind::magnet:
                  {
                    // w' = mu_m |H|^2/2 + B_r . H with H = (B - B_r)/mu_m
                    const double mu_m = mu0 * m.relative_permeability;
                    const double Hx = (B[0] - m.remanence[0]) / mu_m, Hy = (B[1] - m.remanence[1]) / mu_m;
                    w = 0.5 * mu_m * (Hx * Hx + Hy * Hy) + m.remanence[0] * Hx + m.remanence[1] * Hy;
                    break;
                  }
                case Material::Kind::nonlinear:
                  w = m.curve->coenergy_density(m.curve->field_strength(std::sqrt(b2)));
                  break;
              }
            W += w * g.JxW[q];
          }
      }
    return d.depth * W;
  }

  double MagnetostaticProblem::virtual_work_force(double step)
  {
    auto &d = *impl;
    const double s0 = d.s, current = d.current;
    // the state at s0, restored afterwards without recomputing it
    const Vector<double> A0 = d.solution;
    const auto geometry0 = d.cell_geometry;
    const auto velocity0 = d.velocity;
    const std::vector<Point<2>> vertices0 = d.triangulation.get_vertices();
    d.move_to(s0 + step);
    d.solve(current, d.tolerance, 50);
    const double W_plus = coenergy();
    d.solution = A0;
    d.move_to(s0 - step);
    d.solve(current, d.tolerance, 50);
    const double W_minus = coenergy();
    for (const auto &cell : d.triangulation.active_cell_iterators())
      for (unsigned int v = 0; v < 4; ++v)
        cell->vertex(v) = vertices0[cell->vertex_index(v)];
    d.s = s0;
    d.cell_geometry = geometry0;
    d.velocity = velocity0;
    d.solution = A0;
    return (W_plus - W_minus) / (2 * step);
  }

  double MagnetostaticProblem::mean_flux_density(int material, unsigned int component) const
  {
    const auto &d = *impl;
    FEValues<2> fe_values(d.fe, d.quadrature, update_gradients | update_JxW_values);
    std::vector<Tensor<1, 2>> grad_A(d.quadrature.size());
    double sum = 0, area = 0;
    for (const auto &cell : d.dof_handler.active_cell_iterators())
      if (static_cast<int>(cell->material_id()) == material)
        {
          fe_values.reinit(cell);
          fe_values.get_function_gradients(d.solution, grad_A);
          for (unsigned int q = 0; q < grad_A.size(); ++q)
            {
              sum += flux_density(grad_A[q])[component] * fe_values.JxW(q);
              area += fe_values.JxW(q);
            }
        }
    return area > 0 ? sum / area : 0.0;
  }

  double MagnetostaticProblem::max_flux_density(int material) const
  {
    const auto &d = *impl;
    FEValues<2> fe_values(d.fe, d.quadrature, update_gradients);
    std::vector<Tensor<1, 2>> grad_A(d.quadrature.size());
    double largest = 0;
    for (const auto &cell : d.dof_handler.active_cell_iterators())
      if (static_cast<int>(cell->material_id()) == material)
        {
          fe_values.reinit(cell);
          fe_values.get_function_gradients(d.solution, grad_A);
          for (const auto &g : grad_A)
            largest = std::max(largest, g.norm());
        }
    return largest;
  }

  namespace
  {
    /// B, |B| and H from A_z, with the material of each cell.
    class FieldPostprocessor : public DataPostprocessor<2>
    {
    public:
      explicit FieldPostprocessor(const std::map<int, Material> &materials)
        : materials(materials)
      {}

      void evaluate_scalar_field(const DataPostprocessorInputs::Scalar<2> &inputs,
                                 std::vector<Vector<double>> &computed) const override
      {
        const auto cell = inputs.template get_cell<2>();
        const Material &m = materials.at(static_cast<int>(cell->material_id()));
        for (unsigned int q = 0; q < inputs.solution_gradients.size(); ++q)
          {
            const Tensor<1, 2> B = flux_density(inputs.solution_gradients[q]);
            const double b = B.norm();
            double Hx, Hy;
            if (m.kind == Material::Kind::nonlinear)
              {
                const double nu = b > 0 ? m.curve->field_strength(b) / b : 0;
                Hx = nu * B[0], Hy = nu * B[1];
              }
            else
              {
                const double nu = 1 / (mu0 * m.relative_permeability);
                Hx = nu * (B[0] - m.remanence[0]), Hy = nu * (B[1] - m.remanence[1]);
              }
            computed[q] = Vector<double>{B[0], B[1], b, Hx, Hy};
          }
      }

      std::vector<std::string> get_names() const override { return {"B", "B", "B_magnitude", "H", "H"}; }

      std::vector<DataComponentInterpretation::DataComponentInterpretation> get_data_component_interpretation()
        const override
      {
        using I = DataComponentInterpretation::DataComponentInterpretation;
        return {I::component_is_part_of_vector, I::component_is_part_of_vector, I::component_is_scalar,
                I::component_is_part_of_vector, I::component_is_part_of_vector};
      }

      UpdateFlags get_needed_update_flags() const override { return update_gradients; }

    private:
      const std::map<int, Material> &materials;
    };
  } // namespace

  void MagnetostaticProblem::write_vtu(const std::string &filename) const
  {
    const auto &d = *impl;
    FieldPostprocessor postprocessor(d.materials);
    DataOut<2> data_out;
    data_out.attach_dof_handler(d.dof_handler);
    data_out.add_data_vector(d.solution, "A_z");
    data_out.add_data_vector(d.solution, postprocessor);
    Vector<float> material(d.triangulation.n_active_cells()), J(d.triangulation.n_active_cells());
    for (const auto &cell : d.triangulation.active_cell_iterators())
      {
        material[cell->active_cell_index()] = cell->material_id();
        J[cell->active_cell_index()] =
          d.materials.at(static_cast<int>(cell->material_id())).current_density * d.current;
      }
    data_out.add_data_vector(material, "material_id");
    data_out.add_data_vector(J, "current_density");
    data_out.build_patches(d.fe.degree);
    DataOutBase::VtkFlags flags;
    flags.compression_level = DataOutBase::VtkFlags::best_speed;
    data_out.set_flags(flags);
    std::ostringstream out;
    data_out.write_vtu(out);
    write_file_atomically(filename, out.str());
  }

  unsigned int MagnetostaticProblem::n_dofs() const
  {
    return impl->dof_handler.n_dofs();
  }

  unsigned int MagnetostaticProblem::n_cells() const
  {
    return impl->triangulation.n_active_cells();
  }
} // namespace servodrift::magnetics
