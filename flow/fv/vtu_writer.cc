#include "flow/fv/vtu_writer.h"

#include "common/vtu_output.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>

namespace servodrift::flow
{
  void write_fv_vtu(const std::string &filename, const FvMesh &mesh, const std::vector<double> &p,
                    const std::vector<double> &u, const std::vector<double> &v, const std::vector<double> &p_b,
                    const std::vector<double> &u_b, const std::vector<double> &v_b,
                    const std::vector<std::pair<std::string, std::vector<double>>> &extra)
  {
    vtkNew<vtkPoints> points;
    for (const auto &x : mesh.points)
      points->InsertNextPoint(x.x(), x.y(), 0.0);
    vtkNew<vtkUnstructuredGrid> grid;
    grid->SetPoints(points);

    vtkNew<vtkDoubleArray> pressure, velocity;
    pressure->SetName("p");
    velocity->SetName("velocity");
    velocity->SetNumberOfComponents(3);
    vtkNew<vtkIntArray> cell_id, boundary_id;
    cell_id->SetName("cell_id");
    boundary_id->SetName("boundary_id");
    std::vector<vtkNew<vtkDoubleArray>> extras(extra.size());
    for (std::size_t k = 0; k < extra.size(); ++k)
      extras[k]->SetName(extra[k].first.c_str());

    for (std::size_t c = 0; c < mesh.n_cells(); ++c)
      {
        vtkIdType ids[4];
        for (unsigned int k = 0; k < mesh.cell_n_points[c]; ++k)
          ids[k] = mesh.cell_points[c][k];
        grid->InsertNextCell(mesh.cell_n_points[c] == 3 ? VTK_TRIANGLE : VTK_QUAD, mesh.cell_n_points[c], ids);
        pressure->InsertNextValue(p[c]);
        velocity->InsertNextTuple3(u[c], v[c], 0.0);
        cell_id->InsertNextValue(static_cast<int>(c));
        boundary_id->InsertNextValue(-1);
        for (std::size_t k = 0; k < extra.size(); ++k)
          extras[k]->InsertNextValue(extra[k].second[c]);
      }
    for (std::size_t f = 0; f < mesh.n_faces(); ++f)
      if (mesh.neighbour[f] < 0)
        {
          vtkIdType ids[2] = {mesh.face_points[f][0], mesh.face_points[f][1]};
          grid->InsertNextCell(VTK_LINE, 2, ids);
          pressure->InsertNextValue(p_b[f]);
          velocity->InsertNextTuple3(u_b[f], v_b[f], 0.0);
          cell_id->InsertNextValue(-1);
          boundary_id->InsertNextValue(mesh.face_patch[f]);
          for (std::size_t k = 0; k < extra.size(); ++k)
            extras[k]->InsertNextValue(extra[k].second[mesh.owner[f]]);
        }
    grid->GetCellData()->AddArray(pressure);
    grid->GetCellData()->AddArray(velocity);
    grid->GetCellData()->AddArray(cell_id);
    grid->GetCellData()->AddArray(boundary_id);
    for (auto &e : extras)
      grid->GetCellData()->AddArray(e);
    vtkNew<vtkStringArray> names;
    names->SetName("boundary_names");
    for (const auto &n : mesh.patch_names)
      names->InsertNextValue(n);
    grid->GetFieldData()->AddArray(names);

    write_vtu_atomically(filename, grid);
  }
} // namespace servodrift::flow
