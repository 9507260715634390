#include "structure/spring_tube_field_implementation.h"

#include "common/units.h"
#include "common/vtu_output.h"

#include <deal.II/base/quadrature_lib.h>

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>

// What a solution of the spring tube's field model gives beyond its stiffness: the peak von Mises
// stress, the axial stress at a point and the VTU of the tube revolved about its axis.
namespace servodrift::structure
{
  using namespace dealii;
  using spring_tube_field::HarmonicStrain;

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
