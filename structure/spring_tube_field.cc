#include "structure/spring_tube_field_implementation.h"

#include "common/units.h"

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>

#include <algorithm>
#include <cmath>
#include <map>

// The spring tube's field model, the equation: axisymmetric elasticity with Fourier harmonic n = 1
// on the meridian section, clamped base and rigid top (doc/method.md, "Spring tube, field level"),
// solved for the two unit motions of the top; its stiffness from their strain energies.
namespace servodrift::structure
{
  using namespace dealii;
  using spring_tube_field::HarmonicStrain;

  namespace
  {
    constexpr types::boundary_id clamped_base = 1;
    constexpr types::boundary_id rigid_top = 2;

    /// Rigid motion of the top face (z = z_top there): a = b = delta, c = -theta r.
    class RigidTopMotion : public Function<2>
    {
    public:
      RigidTopMotion(double theta, double delta)
        : Function<2>(3)
        , theta(theta)
        , delta(delta)
      {}
      void vector_value(const Point<2> &p, Vector<double> &v) const override
      {
        v[0] = delta;
        v[1] = delta;
        v[2] = -theta * p[0];
      }

    private:
      double theta, delta;
    };

    /// Subdivisions of [x0, x1] into cells of at most `size' (at least one).
    std::vector<double> spacing(double x0, double x1, double size)
    {
      const unsigned int n = std::max(1u, static_cast<unsigned int>(std::ceil((x1 - x0) / size - 1e-9)));
      return std::vector<double>(n, (x1 - x0) / n);
    }

    /// Subdivisions of [x0, x1] that start at `first' next to x0 and grow by 1.25 per cell up to
    /// `largest': fine where a flange or collar meets the wall (a re-entrant corner), coarse outside.
    std::vector<double> graded_spacing(double x0, double x1, double first, double largest)
    {
      std::vector<double> h;
      double sum = 0, next = first;
      while (sum + next < (x1 - x0) * (1 - 1e-9))
        {
          h.push_back(next);
          sum += next;
          next = std::min(1.25 * next, largest);
        }
      if (h.empty())
        return {x1 - x0};
      const double scale = (x1 - x0) / sum; // stretch to fit (the last partial cell is dropped)
      for (double &x : h)
        x *= scale;
      return h;
    }
  } // namespace

  // The meridian section (r, z) as a tensor grid of rectangles with the cells outside the tube's
  // profile removed: the wall r_i..r_o over the whole height, the flange out to its radius below
  // z = 0, the collar out to its radius above z = l. The wall has exactly `wall_layers' cells across,
  // `aspect_ratio' times that size axially; outside the wall the radial size grows from the wall's
  // to the axial size.
  void SpringTubeField::Implementation::make_grid()
  {
    const auto &g = geometry;
    const double r_i = g.inner_diameter / 2, r_o = g.outer_diameter / 2;
    const bool flange = g.base_flange_height > 0, collar = g.top_collar_height > 0;
    const double radial_size = (r_o - r_i) / options.wall_layers;
    const double axial_size = options.aspect_ratio * radial_size;

    std::vector<double> r_breaks{r_i, r_o};
    if (flange)
      r_breaks.push_back(g.base_flange_diameter / 2);
    if (collar)
      r_breaks.push_back(g.top_collar_diameter / 2);
    std::sort(r_breaks.begin() + 2, r_breaks.end());
    r_breaks.erase(std::unique(r_breaks.begin(), r_breaks.end()), r_breaks.end());
    std::vector<double> z_breaks{0.0, g.length};
    if (flange)
      z_breaks.insert(z_breaks.begin(), -g.base_flange_height);
    if (collar)
      z_breaks.push_back(g.length + g.top_collar_height);
    z_top = z_breaks.back();
    section_changes = z_breaks;

    std::vector<std::vector<double>> steps(2);
    std::vector<double> r_lower, z_lower; // lower corner of each column / row of cells
    for (std::size_t k = 0; k + 1 < r_breaks.size(); ++k)
      {
        // the wall: exactly its layers; outside it (flange, collar) graded away from the wall
        const auto s = k == 0 ? spacing(r_breaks[k], r_breaks[k + 1], radial_size)
                              : graded_spacing(r_breaks[k], r_breaks[k + 1], radial_size, axial_size);
        double r = r_breaks[k];
        for (double h : s)
          r_lower.push_back(r), r += h, steps[0].push_back(h);
      }
    for (std::size_t k = 0; k + 1 < z_breaks.size(); ++k)
      {
        const auto s = spacing(z_breaks[k], z_breaks[k + 1], axial_size);
        double z = z_breaks[k];
        for (double h : s)
          z_lower.push_back(z), z += h, steps[1].push_back(h);
      }

    Table<2, types::material_id> material(steps[0].size(), steps[1].size());
    const double eps = 1e-9 * g.length;
    for (std::size_t i = 0; i < r_lower.size(); ++i)
      for (std::size_t j = 0; j < z_lower.size(); ++j)
        {
          const double r_mid = r_lower[i] + 0.5 * steps[0][i], z_mid = z_lower[j] + 0.5 * steps[1][j];
          const bool in_wall = r_mid < r_o;
          const bool in_flange = flange && z_mid < 0 && r_mid < g.base_flange_diameter / 2;
          const bool in_collar = collar && z_mid > g.length && r_mid < g.top_collar_diameter / 2;
          material(i, j) = (in_wall || in_flange || in_collar) ? 0 : numbers::invalid_material_id;
        }
    GridGenerator::subdivided_hyper_rectangle(triangulation, steps, Point<2>(r_i, z_breaks.front()), material);

    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const double z = face->center()[1];
            if (std::abs(z - z_breaks.front()) < eps)
              face->set_boundary_id(clamped_base);
            else if (std::abs(z - z_top) < eps)
              face->set_boundary_id(rigid_top);
          }
  }

  void SpringTubeField::Implementation::setup_system()
  {
    dof_handler.distribute_dofs(fe);
    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp);
    sparsity_pattern.copy_from(dsp);
    stiffness_matrix.reinit(sparsity_pattern);
    constrained_matrix.reinit(sparsity_pattern);

    VectorTools::interpolate_boundary_values(dof_handler, clamped_base, Functions::ZeroFunction<2>(3), base_values);
    VectorTools::interpolate_boundary_values(dof_handler, rigid_top, RigidTopMotion(1, 0), rotation_values);
    VectorTools::interpolate_boundary_values(dof_handler, rigid_top, RigidTopMotion(0, 1), translation_values);
  }

  // a(u, v) = pi int int eps(u) : C : eps(v) r dr dz (the integral over phi of cos^2 and of sin^2
  // is pi for n = 1).
  void SpringTubeField::Implementation::assemble_system()
  {
    const QGauss<2> quadrature(fe.degree + 1);
    FEValues<2> fe_values(fe, quadrature, update_values | update_gradients | update_quadrature_points | update_JxW_values);
    const unsigned int n = fe.n_dofs_per_cell();
    FullMatrix<double> cell_matrix(n, n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<HarmonicStrain> strains;
    strains.reserve(n);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        cell_matrix = 0;
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            const double r = fe_values.quadrature_point(q)[0];
            strains.clear();
            for (unsigned int i = 0; i < n; ++i)
              {
                const unsigned int component = fe.system_to_component_index(i).first;
                std::array<double, 3> value{};
                std::array<Tensor<1, 2>, 3> gradient{};
                value[component] = fe_values.shape_value(i, q);
                gradient[component] = fe_values.shape_grad(i, q);
                strains.emplace_back(value, gradient, r);
              }
            const double weight = units::pi * r * fe_values.JxW(q);
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j <= i; ++j)
                cell_matrix(i, j) += hooke.energy_product(strains[i], strains[j]) * weight;
          }
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = i + 1; j < n; ++j)
            cell_matrix(i, j) = cell_matrix(j, i);
        cell->get_dof_indices(dofs);
        stiffness_matrix.add(dofs, cell_matrix);
      }

    // One factorisation serves both unit motions: the prescribed DOFs (base and top, the same set for
    // both) get identity rows and zero columns; their values enter the right-hand side (lifting).
    constrained_matrix.copy_from(stiffness_matrix);
    std::vector<bool> prescribed(dof_handler.n_dofs(), false);
    for (const auto &[dof, value] : base_values)
      prescribed[dof] = true;
    for (const auto &[dof, value] : rotation_values)
      prescribed[dof] = true;
    for (unsigned int row = 0; row < dof_handler.n_dofs(); ++row)
      for (auto entry = constrained_matrix.begin(row); entry != constrained_matrix.end(row); ++entry)
        if (prescribed[row] || prescribed[entry->column()])
          entry->value() = (entry->column() == row) ? 1.0 : 0.0;
    direct_solver.initialize(constrained_matrix);
  }

  Vector<double> SpringTubeField::Implementation::solve(const std::map<types::global_dof_index, double> &top_values)
  {
    Vector<double> lifting(dof_handler.n_dofs()), rhs(dof_handler.n_dofs());
    for (const auto &[dof, value] : top_values)
      lifting[dof] = value;
    stiffness_matrix.vmult(rhs, lifting);
    rhs *= -1;
    for (const auto &[dof, value] : base_values)
      rhs[dof] = 0;
    for (const auto &[dof, value] : top_values)
      rhs[dof] = value;
    direct_solver.solve(rhs);
    AssertThrow(std::all_of(rhs.begin(), rhs.end(), [](double x) { return std::isfinite(x); }),
                ExcMessage("spring tube field: the elasticity solve gave a non-finite displacement"));
    return rhs;
  }

  SpringTubeField::SpringTubeField(const laws::SpringTubeGeometry &geometry, double E, double nu,
                                   const SpringTubeFieldOptions &options)
    : impl(std::make_unique<Implementation>(geometry, E, nu, options))
  {}

  SpringTubeField::~SpringTubeField() = default;

  void SpringTubeField::run()
  {
    impl->make_grid();
    impl->setup_system();
    impl->assemble_system();
    impl->unit_rotation = impl->solve(impl->rotation_values);
    impl->unit_translation = impl->solve(impl->translation_values);
    // Generalised forces of the top from the strain energy: S_ij = a(u_i, u_j) for the solutions of
    // the unit motions (no load in the body, so a(u_i, u_j) is the work of the top's reactions).
    const Vector<double> *mode[2] = {&impl->unit_rotation, &impl->unit_translation};
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        impl->top_stiffness[i][j] = impl->stiffness_matrix.matrix_scalar_product(*mode[i], *mode[j]);
  }

  Matrix2 SpringTubeField::stiffness() const { return impl->top_stiffness; }
  Matrix2 SpringTubeField::compliance() const { return impl->compliance(); }
  double SpringTubeField::rotational_stiffness() const { return 1.0 / impl->compliance()[0][0]; }

  std::array<double, 2> SpringTubeField::top_motion(const TopLoad &load) const
  {
    const auto C = impl->compliance();
    return {C[0][0] * load.moment + C[0][1] * load.shear, C[1][0] * load.moment + C[1][1] * load.shear};
  }
} // namespace servodrift::structure
