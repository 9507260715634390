#include "structure/spring_tube_field.h"

#include "common/error.h"
#include "common/units.h"
#include "common/vtu_output.h"

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace servodrift::structure
{
  using namespace dealii;

  namespace
  {
    constexpr types::boundary_id clamped_base = 1;
    constexpr types::boundary_id rigid_top = 2;

    /// Strain of the n = 1 harmonic displacement (a, b, c) of the header, split into the parts that
    /// vary as cos phi (eps_rr, eps_phiphi, eps_zz, gamma_rz) and as sin phi (gamma_rphi, gamma_zphi).
    /// Cylindrical small strains with u_r = a cos, u_phi = -b sin, u_z = c cos:
    ///   eps_rr = a_r,  eps_phiphi = (a - b)/r,  eps_zz = c_z,  gamma_rz = a_z + c_r,
    ///   gamma_rphi = -(b_r + (a - b)/r),  gamma_zphi = -(b_z + c/r).
    /// Both rigid motions of the header give zero strain.
    struct HarmonicStrain
    {
      double rr, phiphi, zz, rz; // cos phi part
      double rphi, zphi;         // sin phi part

      HarmonicStrain(const std::array<double, 3> &value, const std::array<Tensor<1, 2>, 3> &gradient, double r)
        : rr(gradient[0][0])
        , phiphi((value[0] - value[1]) / r)
        , zz(gradient[2][1])
        , rz(gradient[0][1] + gradient[2][0])
        , rphi(-(gradient[1][0] + (value[0] - value[1]) / r))
        , zphi(-(gradient[1][1] + value[2] / r))
      {}
    };

    /// Isotropic Hooke's law on the two parts; the strain energy density averaged over phi is
    /// (cos part + sin part)/2, and its integral over phi gives the factor pi of the bilinear form.
    struct Hooke
    {
      double lambda, mu;

      /// eps : C : eps' for the cos part plus the sin part (the integrand of a(u, v) / pi).
      double energy_product(const HarmonicStrain &e, const HarmonicStrain &f) const
      {
        const double tr_e = e.rr + e.phiphi + e.zz, tr_f = f.rr + f.phiphi + f.zz;
        return lambda * tr_e * tr_f + 2 * mu * (e.rr * f.rr + e.phiphi * f.phiphi + e.zz * f.zz) +
               mu * (e.rz * f.rz + e.rphi * f.rphi + e.zphi * f.zphi);
      }

      struct Stress
      {
        double rr, phiphi, zz, rz, rphi, zphi;
        /// von Mises stress squared = A cos^2 phi + B sin^2 phi: the normal stresses and tau_rz
        /// scale with cos phi, tau_rphi and tau_zphi with sin phi.
        double von_mises_cos_part() const
        {
          return 0.5 * ((rr - phiphi) * (rr - phiphi) + (phiphi - zz) * (phiphi - zz) + (zz - rr) * (zz - rr)) +
                 3 * rz * rz;
        }
        double von_mises_sin_part() const { return 3 * (rphi * rphi + zphi * zphi); }
      };

      Stress stress(const HarmonicStrain &e) const
      {
        const double tr = e.rr + e.phiphi + e.zz;
        return {lambda * tr + 2 * mu * e.rr, lambda * tr + 2 * mu * e.phiphi, lambda * tr + 2 * mu * e.zz,
                mu * e.rz, mu * e.rphi, mu * e.zphi};
      }
    };

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

  struct SpringTubeField::Implementation
  {
    laws::SpringTubeGeometry geometry;
    Hooke hooke;
    SpringTubeFieldOptions options;

    Triangulation<2> triangulation;
    FESystem<2> fe;
    DoFHandler<2> dof_handler;
    SparsityPattern sparsity_pattern;
    SparseMatrix<double> stiffness_matrix;  // a(u, v), unconstrained
    SparseMatrix<double> constrained_matrix; // clamped and rigid DOFs eliminated (identity rows)
    SparseDirectUMFPACK direct_solver;
    std::map<types::global_dof_index, double> base_values, rotation_values, translation_values;
    Vector<double> unit_rotation, unit_translation; // solutions for theta = 1 and for delta = 1
    Matrix2 top_stiffness{};
    double z_top = 0;
    std::vector<double> section_changes; // heights of the base, the junctions and the top

    Implementation(const laws::SpringTubeGeometry &g, double E, double nu, const SpringTubeFieldOptions &o)
      : geometry(g)
      , hooke{E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))}
      , options(o)
      , fe(FE_Q<2>(o.element_degree), 3)
      , dof_handler(triangulation)
    {}

    void make_grid();
    void setup_system();
    void assemble_system();
    Vector<double> solve(const std::map<types::global_dof_index, double> &top_values);

    /// Calls `f(cell, q, point, strain)' at each point of `quadrature' in every cell, for the displacement u.
    template <typename F>
    void for_each_point(const Vector<double> &u, const Quadrature<2> &quadrature, F &&f) const
    {
      FEValues<2> fe_values(fe, quadrature, update_values | update_gradients | update_quadrature_points);
      std::vector<Vector<double>> values(quadrature.size(), Vector<double>(3));
      std::vector<std::vector<Tensor<1, 2>>> gradients(quadrature.size(), std::vector<Tensor<1, 2>>(3));
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          fe_values.reinit(cell);
          fe_values.get_function_values(u, values);
          fe_values.get_function_gradients(u, gradients);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              const Point<2> &x = fe_values.quadrature_point(q);
              f(cell, q, x, HarmonicStrain({values[q][0], values[q][1], values[q][2]},
                                           {gradients[q][0], gradients[q][1], gradients[q][2]}, x[0]));
            }
        }
    }

    /// Strain of u at a point of the meridian section (on a boundary, from the cell that holds it).
    HarmonicStrain strain_at(const Vector<double> &u, const Point<2> &x) const
    {
      const auto [cell, unit_point] = GridTools::find_active_cell_around_point(MappingQ1<2>(), dof_handler, x);
      AssertThrow(cell.state() == IteratorState::valid, ExcMessage("spring tube field: point outside the tube"));
      const Quadrature<2> point(GeometryInfo<2>::project_to_unit_cell(unit_point));
      FEValues<2> fe_values(fe, point, update_values | update_gradients);
      fe_values.reinit(cell);
      std::vector<Vector<double>> value(1, Vector<double>(3));
      std::vector<std::vector<Tensor<1, 2>>> gradient(1, std::vector<Tensor<1, 2>>(3));
      fe_values.get_function_values(u, value);
      fe_values.get_function_gradients(u, gradient);
      return HarmonicStrain({value[0][0], value[0][1], value[0][2]}, {gradient[0][0], gradient[0][1], gradient[0][2]},
                            x[0]);
    }

    Vector<double> displacement(const TopLoad &load) const
    {
      const auto C = compliance();
      const double theta = C[0][0] * load.moment + C[0][1] * load.shear;
      const double delta = C[1][0] * load.moment + C[1][1] * load.shear;
      Vector<double> u(unit_rotation);
      u *= theta;
      u.add(delta, unit_translation);
      return u;
    }

    Matrix2 compliance() const
    {
      const auto &S = top_stiffness;
      const double det = S[0][0] * S[1][1] - S[0][1] * S[1][0];
      return {{{S[1][1] / det, -S[0][1] / det}, {-S[1][0] / det, S[0][0] / det}}};
    }
  };

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

  StressPeak SpringTubeField::peak_stress(const TopLoad &load, double end_distance) const
  {
    const Vector<double> u = impl->displacement(load);
    StressPeak peak;
    const auto consider = [&](const Point<2> &x, const HarmonicStrain &e) {
      const auto s = impl->hooke.stress(e);
      // max over phi of sqrt(A cos^2 + B sin^2) is sqrt(max(A, B))
      const double vm = std::sqrt(std::max(s.von_mises_cos_part(), s.von_mises_sin_part()));
      if (vm > peak.von_mises)
        peak = {vm, x[0], x[1]};
    };
    // Gauss-Lobatto points include the cell boundaries, so the surfaces are sampled
    impl->for_each_point(u, QGaussLobatto<2>(impl->fe.degree + 1),
                         [&](const auto &, unsigned int, const Point<2> &x, const HarmonicStrain &e) {
                           for (double z : impl->section_changes)
                             if (std::abs(x[1] - z) < end_distance)
                               return;
                           consider(x, e);
                         });
    // The stress decays away from the ends, so the largest beside them is at exactly end_distance:
    // sample the wall's surfaces there too (otherwise the answer would depend on where the
    // nodes fall).
    if (end_distance > 0)
      {
        const double r_i = impl->geometry.inner_diameter / 2, r_o = impl->geometry.outer_diameter / 2;
        for (double z : impl->section_changes)
          for (double height : {z - end_distance, z + end_distance})
            for (double r : {r_i, r_o})
              if (height > impl->section_changes.front() && height < impl->z_top)
                consider(Point<2>(r, height), impl->strain_at(u, Point<2>(r, height)));
      }
    return peak;
  }

  double SpringTubeField::axial_stress(const TopLoad &load, double radius, double height) const
  {
    const Vector<double> u = impl->displacement(load);
    return impl->hooke.stress(impl->strain_at(u, Point<2>(radius, height))).zz;
  }

  void SpringTubeField::write_vtu(const std::string &filename, const TopLoad &load, unsigned int segments) const
  {
    const Vector<double> u = impl->displacement(load);
    const auto &tria = impl->triangulation;
    const unsigned int n_vertices = tria.n_vertices();

    // Harmonic amplitudes at the vertices: displacement (continuous) and the stress parts (averaged
    // over the cells that share a vertex).
    std::vector<std::array<double, 3>> amplitude(n_vertices);
    std::vector<double> vm_cos(n_vertices, 0), vm_sin(n_vertices, 0), sigma_zz(n_vertices, 0), count(n_vertices, 0);
    std::vector<Point<2>> corners;
    for (unsigned int v = 0; v < GeometryInfo<2>::vertices_per_cell; ++v)
      corners.push_back(GeometryInfo<2>::unit_cell_vertex(v));
    const Quadrature<2> at_vertices(corners);
    FEValues<2> fe_values(impl->fe, at_vertices, update_values);
    std::vector<Vector<double>> values(corners.size(), Vector<double>(3));
    impl->for_each_point(u, at_vertices, [&](const auto &cell, unsigned int q, const Point<2> &, const HarmonicStrain &e) {
      const unsigned int v = cell->vertex_index(q);
      const auto s = impl->hooke.stress(e);
      vm_cos[v] += s.von_mises_cos_part();
      vm_sin[v] += s.von_mises_sin_part();
      sigma_zz[v] += s.zz;
      count[v] += 1;
    });
    for (const auto &cell : impl->dof_handler.active_cell_iterators())
      {
        fe_values.reinit(cell);
        fe_values.get_function_values(u, values);
        for (unsigned int q = 0; q < corners.size(); ++q)
          amplitude[cell->vertex_index(q)] = {values[q][0], values[q][1], values[q][2]};
      }

    vtkNew<vtkPoints> points;
    vtkNew<vtkDoubleArray> displacement, von_mises, axial;
    displacement->SetName("displacement");
    displacement->SetNumberOfComponents(3);
    von_mises->SetName("von_Mises_stress");
    axial->SetName("axial_stress");
    const auto &vertices = tria.get_vertices();
    for (unsigned int k = 0; k < segments; ++k)
      {
        const double phi = 2 * units::pi * k / segments, c = std::cos(phi), s = std::sin(phi);
        for (unsigned int v = 0; v < n_vertices; ++v)
          {
            const double r = vertices[v][0], z = vertices[v][1];
            points->InsertNextPoint(r * c, r * s, z);
            const auto &[a, b, w] = amplitude[v];
            const double u_r = a * c, u_phi = -b * s, u_z = w * c;
            displacement->InsertNextTuple3(u_r * c - u_phi * s, u_r * s + u_phi * c, u_z);
            const double n = std::max(count[v], 1.0);
            von_mises->InsertNextValue(std::sqrt(std::max(0.0, vm_cos[v] / n * c * c + vm_sin[v] / n * s * s)));
            axial->InsertNextValue(sigma_zz[v] / n * c);
          }
      }
    vtkNew<vtkUnstructuredGrid> grid;
    grid->SetPoints(points);
    for (const auto &cell : tria.active_cell_iterators())
      for (unsigned int k = 0; k < segments; ++k)
        {
          // deal.II's vertex order 0 1 2 3 is lexicographic; VTK's quad goes 0 1 3 2. The face at
          // phi_{k+1} comes first so that the hexahedron has a positive volume.
          const vtkIdType next = ((k + 1) % segments) * n_vertices, here = k * n_vertices;
          const unsigned int q[4] = {cell->vertex_index(0), cell->vertex_index(1), cell->vertex_index(3),
                                     cell->vertex_index(2)};
          vtkIdType ids[8];
          for (unsigned int j = 0; j < 4; ++j)
            ids[j] = next + q[j], ids[4 + j] = here + q[j];
          grid->InsertNextCell(VTK_HEXAHEDRON, 8, ids);
        }
    grid->GetPointData()->AddArray(displacement);
    grid->GetPointData()->AddArray(von_mises);
    grid->GetPointData()->AddArray(axial);
    vtkNew<vtkDoubleArray> load_data;
    load_data->SetName("top_moment_and_shear");
    load_data->SetNumberOfComponents(2);
    load_data->InsertNextTuple2(load.moment, load.shear);
    grid->GetFieldData()->AddArray(load_data);

    write_vtu_atomically(filename, grid);
  }

  unsigned int SpringTubeField::n_dofs() const { return impl->dof_handler.n_dofs(); }
  unsigned int SpringTubeField::n_cells() const { return impl->triangulation.n_active_cells(); }
} // namespace servodrift::structure
