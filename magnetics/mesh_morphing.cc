// The moving body by mesh morphing (model.md 4.1): its vertices move rigidly, the morphing air's
// follow a Laplace extension of that motion, assembled and factorised once per mesh; the body's
// virtual velocity is extended the same way, for the weighted Maxwell stress tensor. A rigid
// motion's displacement and velocity are combinations of two fixed fields on the body (rotation: r
// and e_z x r) and the extension is linear, so the two are extended once per mesh and every
// position is their combination.
#include "magnetics/magnetostatic_problem_implementation.h"

#include <deal.II/fe/fe_values.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace servodrift::magnetics
{
  using detail::check;

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
    extended_motion_fields = extend(motion_fields());
    move_to(0.0); // sizes the virtual velocity too
  }

  Eigen::MatrixXd MagnetostaticProblem::Implementation::motion_fields() const
  {
    // rotation about p: F1 = r = x - p and F2 = e_z x r; translation: F1 = d, F2 = 0
    const unsigned int n = morph_dof_handler.n_dofs();
    Eigen::MatrixXd fields = Eigen::MatrixXd::Zero(n, 4);
    for (unsigned int d = 0; d < n; ++d)
      if (moving_dof[d])
        {
          if (motion.kind == Motion::Kind::translation)
            {
              fields.row(d) << motion.direction[0], motion.direction[1], 0, 0;
              continue;
            }
          const Point<2> &x = reference_vertices[vertex_of_dof[d]];
          const double rx = x[0] - motion.point[0], ry = x[1] - motion.point[1];
          fields.row(d) << rx, ry, -ry, rx;
        }
    return fields;
  }

  std::array<double, 4> MagnetostaticProblem::Implementation::motion_coefficients(double position) const
  {
    if (motion.kind == Motion::Kind::translation)
      return {position, 0, 1, 0}; // u = s d, w = d
    // u = R(s) r - r = (cos s - 1) r + sin s (e_z x r); w = e_z x R(s) r = -sin s r + cos s (e_z x r)
    const double c = std::cos(position), sn = std::sin(position);
    return {c - 1, sn, -sn, c};
  }

  Eigen::MatrixXd MagnetostaticProblem::Implementation::extend(const Eigen::MatrixXd &boundary) const
  {
    // U_F = -K_ff^-1 K_fd U_D, every column in one solve (the supernodal factor's triangular solves
    // then run as matrix-matrix products)
    const Eigen::Index n = boundary.rows(), m = boundary.cols();
    Eigen::MatrixXd field = Eigen::MatrixXd::Zero(n, m), U_D(K_fd.cols(), m);
    for (Eigen::Index d = 0; d < n; ++d)
      if (fixed_index[d] >= 0)
        {
          U_D.row(fixed_index[d]) = boundary.row(d);
          field.row(d) = boundary.row(d);
        }
    if (K_ff.rows() == 0)
      return field;
    const Eigen::MatrixXd rhs_free = -(K_fd * U_D);
    const Eigen::MatrixXd U_F = morph_cholesky.solve(rhs_free);
    check(morph_cholesky, "the mesh-morphing solve");
    for (Eigen::Index d = 0; d < n; ++d)
      if (free_index[d] >= 0)
        field.row(d) = U_F.row(free_index[d]);
    return field;
  }

  void MagnetostaticProblem::Implementation::move_to(double position)
  {
    // the body's displacement u and its virtual velocity w at the new position (for the MST), both
    // extended into the air: combinations of the two extended motion fields
    const unsigned int n = morph_dof_handler.n_dofs();
    const auto [a_u, b_u, a_w, b_w] = motion_coefficients(position);
    const Eigen::MatrixXd &F = extended_motion_fields;
    Eigen::MatrixXd extended(n, 4);
    extended.leftCols(2) = a_u * F.leftCols(2) + b_u * F.rightCols(2);
    extended.rightCols(2) = a_w * F.leftCols(2) + b_w * F.rightCols(2);

    std::vector<Point<2>> moved(reference_vertices.size());
    for (unsigned int d = 0; d < n; ++d)
      {
        const unsigned int v = vertex_of_dof[d];
        moved[v] = reference_vertices[v] + Point<2>(extended(d, 0), extended(d, 1));
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
    for (unsigned int k = 0; k < 2; ++k)
      {
        velocity[k].reinit(n);
        for (unsigned int d = 0; d < n; ++d)
          velocity[k][d] = extended(d, 2 + k);
      }
  }

  void MagnetostaticProblem::Implementation::update_cell_geometry()
  {
    FEValues<2> fe_values(fe, quadrature, update_gradients | update_JxW_values);
    const unsigned int dofs_per_cell = fe.n_dofs_per_cell(), n_q = quadrature.size();
    // The solids that stay never change: a buffer filled whole once (virtual work swaps in its own
    // at its first use) keeps their entries, and only the moving body and the morphing air are redone.
    const bool whole = cell_geometry.JxW.size() != triangulation.n_active_cells() * n_q;
    cell_geometry.JxW.resize(triangulation.n_active_cells() * n_q);
    cell_geometry.shape_gradients.resize(triangulation.n_active_cells() * n_q * dofs_per_cell);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const Material &m = *cell_material[cell->active_cell_index()];
        if (!whole && !m.moving && !m.morphing)
          continue;
        fe_values.reinit(cell);
        const std::size_t first_q = cell->active_cell_index() * n_q;
        for (unsigned int q = 0; q < n_q; ++q)
          {
            cell_geometry.JxW[first_q + q] = fe_values.JxW(q);
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              cell_geometry.shape_gradients[(first_q + q) * dofs_per_cell + i] = fe_values.shape_grad(i, q);
          }
      }
  }
} // namespace servodrift::magnetics
