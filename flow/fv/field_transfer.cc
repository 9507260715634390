#include "flow/fv/field_transfer.h"

#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStaticPointLocator.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace servodrift::flow
{
  namespace
  {
    /// source cells per target cell: enough to smooth the piecewise-constant source without
    /// reaching across more than a cell or two of the (graded) source mesh
    constexpr int neighbours = 4;
  } // namespace

  FlowFields transfer_fields(const FvMesh &from, const FlowFields &fields, const FvMesh &to)
  {
    if (fields.u.size() != from.n_cells())
      throw std::invalid_argument("flow: transfer_fields: the fields are not those of " + from.source);
    // the source cell centres in VTK's static point locator (a uniform bucket grid built once)
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble(); // VTK's default float would blur the micrometre cells of the gap
    points->SetNumberOfPoints(vtkIdType(from.n_cells()));
    for (std::size_t c = 0; c < from.n_cells(); ++c)
      points->SetPoint(vtkIdType(c), from.cell_center[c].x(), from.cell_center[c].y(), 0.0);
    vtkNew<vtkPolyData> cloud;
    cloud->SetPoints(points);
    vtkNew<vtkStaticPointLocator> locator;
    locator->SetDataSet(cloud);
    locator->BuildLocator();

    FlowFields out;
    out.density = fields.density;
    out.turbulent = fields.turbulent;
    out.boundary_pressures = fields.boundary_pressures;
    out.face_area = to.face_area;
    const bool cavitation = fields.liquid_fraction.size() == from.n_cells();
    struct Carried
    {
      const std::vector<double> *source;
      std::vector<double> *target;
    };
    std::vector<Carried> carried{{&fields.u, &out.u}, {&fields.v, &out.v}, {&fields.p, &out.p}};
    if (fields.turbulent)
      carried.insert(carried.end(), {{&fields.k, &out.k}, {&fields.epsilon, &out.epsilon},
                                     {&fields.turbulent_viscosity, &out.turbulent_viscosity}});
    if (cavitation)
      carried.push_back({&fields.liquid_fraction, &out.liquid_fraction}), out.cavitating.resize(to.n_cells());
    for (auto &c : carried)
      c.target->resize(to.n_cells());

    vtkNew<vtkIdList> nearest;
    for (std::size_t cell = 0; cell < to.n_cells(); ++cell)
      {
        const double x[3] = {to.cell_center[cell].x(), to.cell_center[cell].y(), 0.0};
        locator->FindClosestNPoints(neighbours, x, nearest); // sorted by distance
        double weights[neighbours], sum = 0;
        int n = int(nearest->GetNumberOfIds());
        for (int j = 0; j < n; ++j)
          {
            const double distance = (from.cell_center[std::size_t(nearest->GetId(j))] - to.cell_center[cell]).norm();
            if (distance <= 1e-12 * to.cell_center[cell].norm())
              {
                n = 1, weights[0] = sum = 1; // a coincident centre (the same mesh): its value exactly
                break;
              }
            weights[j] = 1 / distance;
            sum += weights[j];
          }
        for (auto &c : carried)
          {
            double value = 0;
            for (int j = 0; j < n; ++j)
              value += weights[j] / sum * (*c.source)[std::size_t(nearest->GetId(j))];
            (*c.target)[cell] = value;
          }
        if (cavitation)
          {
            out.cavitating[cell] = fields.cavitating[std::size_t(nearest->GetId(0))];
            if (!out.cavitating[cell])
              out.liquid_fraction[cell] = 1;
          }
      }
    return out;
  }
} // namespace servodrift::flow
