#pragma once
// Each cell centre's distance to the nearest wall, for the wall treatments of the turbulence models.
#include "flow/fv/boundary_conditions.h"

#include <vector>

namespace servodrift::flow
{
  /// The shortest distance from each cell centre to a wall face (a segment) [m]; by brute force:
  /// the valve's meshes have a few thousand wall faces, and it runs once per mesh.
  std::vector<double> wall_distance(const FvMesh &mesh, const BoundaryConditions &boundaries);
} // namespace servodrift::flow
