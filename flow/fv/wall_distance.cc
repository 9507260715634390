#include "flow/fv/wall_distance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace servodrift::flow
{
  std::vector<double> wall_distance(const FvMesh &mesh, const BoundaryConditions &boundaries)
  {
    std::vector<std::array<Vector2, 2>> walls;
    mesh.for_each_boundary_face([&](std::size_t f, unsigned int) {
      if (boundaries.kind(f) == BoundaryCondition::Kind::wall)
        walls.push_back({mesh.points[mesh.face_points[f][0]], mesh.points[mesh.face_points[f][1]]});
    });
    std::vector<double> distance(mesh.n_cells());
    for (std::size_t c = 0; c < mesh.n_cells(); ++c)
      {
        const Vector2 &x = mesh.cell_center[c];
        double best = std::numeric_limits<double>::max();
        for (const auto &w : walls)
          {
            const Vector2 t = w[1] - w[0];
            const double s = std::clamp((x - w[0]).dot(t) / t.squaredNorm(), 0.0, 1.0);
            best = std::min(best, (x - w[0] - s * t).squaredNorm());
          }
        distance[c] = std::sqrt(best);
      }
    return distance;
  }
} // namespace servodrift::flow
