// The A_z equation of the planar torque motor (model.md 4.1): set-up on one mesh, assembly of its
// residual and Newton matrix, and the Newton solve with chord steps and line search.
#include "magnetics/magnetostatic_problem_implementation.h"

#include "common/units.h"

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace servodrift::magnetics
{
  using units::mu0;
  using detail::check;

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

    // what the assembly needs of each cell that the motion does not change
    const unsigned int dofs_per_cell = fe.n_dofs_per_cell(), n_q = quadrature.size();
    cell_dofs.resize(triangulation.n_active_cells() * dofs_per_cell);
    cell_material.resize(triangulation.n_active_cells());
    std::vector<types::global_dof_index> dofs(dofs_per_cell);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        std::copy(dofs.begin(), dofs.end(), cell_dofs.begin() + std::ptrdiff_t(cell->active_cell_index() * dofs_per_cell));
        cell_material[cell->active_cell_index()] = &material(cell);
      }
    shape_values.reinit(n_q, dofs_per_cell);
    for (unsigned int q = 0; q < n_q; ++q)
      for (unsigned int i = 0; i < dofs_per_cell; ++i)
        shape_values(q, i) = fe.shape_value(i, quadrature.point(q));
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
    std::vector<types::global_dof_index> dofs(dofs_per_cell);
    for (std::size_t c = 0; c < cell_material.size(); ++c)
      {
        const Material &m = *cell_material[c];
        const types::global_dof_index *cell_dof = &cell_dofs[c * dofs_per_cell];
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          A_local[i] = A[dofs[i] = cell_dof[i]];
        cell_matrix = 0;
        cell_rhs = 0;
        const double J = m.current_density * current;
        const double Brx = m.remanence[0], Bry = m.remanence[1]; // magnet: H = nu_m (B - B_r)
        for (unsigned int q = 0; q < n_q; ++q)
          {
            const double JxW = cell_geometry.JxW[c * n_q + q];
            const Tensor<1, 2> *grad = &cell_geometry.shape_gradients[(c * n_q + q) * dofs_per_cell];
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
          constraints.distribute_local_to_global(cell_matrix, cell_rhs, dofs, jacobian, rhs);
        else
          constraints.distribute_local_to_global(cell_rhs, dofs, rhs);
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
    stats.start_residual = r;
    bool chord_contracts = true;

    // Chord steps on the last factorisation (the previous angle's or current's, often the same mesh
    // position, or this solve's last Newton step's) while each cuts the residual at least tenfold;
    // where one does not, a Newton step with a fresh Jacobian and a backtracking line search on the
    // residual norm (Armijo), whose factorisation the chord steps then reuse. Near the solution a
    // fresh factorisation contracts far more than tenfold, so one Newton step is followed by chord
    // steps (a triangular solve and a residual each) instead of a factorisation per step.
    while (r > target)
      {
        if (stats.iterations >= max_iterations)
          throw std::runtime_error("magnetostatics: Newton did not converge in " + std::to_string(max_iterations) +
                                   " iterations (residual " + std::to_string(r / stats.initial_residual) +
                                   " of the initial one)");
        if (have_factorization && chord_contracts)
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
            const double r_trial = residual_norm(trial); // rhs is now the trial's
            ++stats.iterations;
            if (r_trial < 0.1 * r)
              {
                solution = trial;
                r = r_trial;
                continue;
              }
            chord_contracts = false;
          }
        assemble_system(solution, true);
        solve_linear_system(update);
        have_factorization = chord_contracts = true;
        ++stats.iterations;
        double alpha = 1, r_trial = 0;
        for (int halvings = 0;; ++halvings)
          {
            trial = solution;
            trial.add(alpha, update);
            r_trial = residual_norm(trial); // the last one evaluated is the accepted one: rhs is its residual
            if (r_trial <= (1 - 1e-4 * alpha) * r || halvings == 30)
              break;
            alpha /= 2;
          }
        if (!(r_trial < r))
          throw std::runtime_error("magnetostatics: the Newton line search found no decrease of the residual");
        solution = trial;
        r = r_trial;
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
    // In a sweep over positions the solution before the move is a zeroth-order start; where virtual
    // work left dA/ds and d2A/ds2 at this current, or the last solves at this current lie on a
    // parabola, the second-order one (Taylor). RV-1's sweep: the starting residual 1.8e-2 of
    // ||R(0)|| from the solution before, 7e-4 to first order, 2e-5 to second order from virtual
    // work's derivatives (doc/changes.md, issue 63: the torque motor). Without virtual work's
    // solves, the parabola's cut a temperature's Newton and chord steps from 181 to 162 (RV-1,
    // 40 degC; virtual work's derivatives: 138, at two more solves per case).
    auto &d = *impl;
    if (d.tangent.known && d.tangent.current == current && d.tangent.position != d.s)
      {
        const double ds = d.s - d.tangent.position;
        d.solution = d.tangent.A;
        d.solution.add(ds, d.tangent.dA_ds, 0.5 * ds * ds, d.tangent.d2A_ds2);
      }
    const NewtonStatistics statistics = impl->solve(current, tolerance, max_iterations);
    impl->remember_solve();
    return statistics;
  }

  void MagnetostaticProblem::Implementation::remember_solve()
  {
    if (!solved.empty() && (solved.back().current != current || solved.back().position == s))
      solved.clear(); // another current: its solves say nothing of this one's path; the same position: no step
    if (solved.size() == 3)
      solved.erase(solved.begin());
    solved.push_back({s, current, solution});
    if (solved.size() < 2)
      return;
    // Newton's divided differences about the newest point s2: P(s) = A2 + (s - s2) f21 + (s - s2)(s - s1) f210
    const Solved &p2 = solved.back(), &p1 = solved[solved.size() - 2];
    Vector<double> f21 = p2.A;
    f21.add(-1, p1.A);
    f21 /= p2.position - p1.position;
    tangent.d2A_ds2.reinit(f21.size());
    tangent.dA_ds = f21;
    if (solved.size() == 3)
      {
        const Solved &p0 = solved.front();
        Vector<double> f210 = p1.A;
        f210.add(-1, p0.A);
        f210 /= p1.position - p0.position; // f10
        f210.sadd(-1, 1, f21);
        f210 /= p2.position - p0.position;
        tangent.dA_ds.add(p2.position - p1.position, f210);
        tangent.d2A_ds2.add(2, f210);
      }
    tangent.A = p2.A;
    tangent.position = p2.position, tangent.current = current, tangent.known = true;
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
