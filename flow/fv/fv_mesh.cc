#include "flow/fv/fv_mesh.h"

#include "common/error.h"

#include <Eigen/Dense>

#include <cmath>
#include <map>

namespace servodrift::flow
{
  FvMesh::FvMesh(const PlanarMesh &mesh, Geometry geometry_, std::string source_)
    : geometry(geometry_)
    , source(std::move(source_))
  {
    for (const auto &p : mesh.vertices)
      points.emplace_back(p[0], p[1]);
    if (geometry == Geometry::axisymmetric)
      for (const auto &p : points)
        if (p.y() < -1e-12)
          throw InputError(source + ": an axisymmetric mesh must lie in r = y >= 0 (a point is at r = " +
                           format_number(p.y()) + ")");

    // cells: centroid and volume of the polygon (axisymmetric: int r dA = A r_centroid, exact)
    for (const auto &c : mesh.cells)
      {
        cell_points.push_back(c.vertices);
        cell_n_points.push_back(c.n_vertices);
        double A = 0, cx = 0, cy = 0;
        for (unsigned int k = 0; k < c.n_vertices; ++k)
          {
            const Vector2 &a = points[c.vertices[k]], &b = points[c.vertices[(k + 1) % c.n_vertices]];
            const double cross = a.x() * b.y() - b.x() * a.y();
            A += cross;
            cx += (a.x() + b.x()) * cross;
            cy += (a.y() + b.y()) * cross;
          }
        A *= 0.5;
        if (!(A > 0))
          throw InputError(source + ": a degenerate cell (area " + format_number(A) + ")");
        const Vector2 centroid(cx / (6 * A), cy / (6 * A));
        cell_center.push_back(centroid);
        cell_volume.push_back(geometry == Geometry::planar ? A : A * centroid.y());
      }
    if (geometry == Geometry::axisymmetric)
      for (double V : cell_volume)
        if (!(V > 0))
          throw InputError(source + ": a cell touches the axis with no area off it");

    // faces: each edge once; interior edges have two cells
    std::map<std::pair<unsigned int, unsigned int>, std::size_t> edge_face;
    cell_faces.resize(n_cells());
    for (std::size_t c = 0; c < n_cells(); ++c)
      for (unsigned int k = 0; k < cell_n_points[c]; ++k)
        {
          const unsigned int a = cell_points[c][k], b = cell_points[c][(k + 1) % cell_n_points[c]];
          const auto key = std::make_pair(std::min(a, b), std::max(a, b));
          const auto found = edge_face.find(key);
          if (found == edge_face.end())
            {
              const std::size_t f = owner.size();
              edge_face[key] = f;
              owner.push_back(static_cast<unsigned int>(c));
              neighbour.push_back(-1);
              face_points.push_back({a, b}); // counterclockwise for the owner: outward normal to the right
              cell_faces[c].push_back(static_cast<unsigned int>(f));
            }
          else
            {
              if (neighbour[found->second] != -1)
                throw InputError(source + ": an edge is shared by more than two cells");
              neighbour[found->second] = static_cast<int>(c);
              cell_faces[c].push_back(static_cast<unsigned int>(found->second));
            }
        }
    for (std::size_t f = 0; f < n_faces(); ++f)
      {
        const Vector2 &a = points[face_points[f][0]], &b = points[face_points[f][1]];
        const Vector2 t = b - a;
        const double length = t.norm();
        face_center.push_back(0.5 * (a + b));
        face_normal.emplace_back(t.y() / length, -t.x() / length);
        face_area.push_back(geometry == Geometry::planar ? length : length * 0.5 * (a.y() + b.y()));
      }

    // boundary patches
    face_patch.assign(n_faces(), -1);
    std::map<int, int> patch_of_boundary;
    for (const auto &[id, name] : mesh.boundary_names)
      {
        patch_of_boundary[id] = static_cast<int>(patch_names.size());
        patch_names.push_back(name);
      }
    patch_faces.resize(patch_names.size());
    for (const auto &bf : mesh.boundary_faces)
      {
        const auto key = std::make_pair(std::min(bf.vertices[0], bf.vertices[1]), std::max(bf.vertices[0], bf.vertices[1]));
        const auto found = edge_face.find(key);
        if (found == edge_face.end() || neighbour[found->second] != -1)
          continue; // a named curve inside the domain: not a boundary
        face_patch[found->second] = patch_of_boundary.at(bf.boundary);
      }
    for (std::size_t f = 0; f < n_faces(); ++f)
      if (neighbour[f] == -1)
        {
          if (face_patch[f] < 0)
            throw InputError(source + ": a boundary edge at (" + format_number(face_center[f].x()) + ", " +
                             format_number(face_center[f].y()) + ") belongs to no physical curve (name every boundary)");
          patch_faces[face_patch[f]].push_back(static_cast<unsigned int>(f));
        }

    // interpolation weights and least-squares gradient operators
    weight.assign(n_faces(), 1.0);
    for (std::size_t f = 0; f < n_faces(); ++f)
      if (neighbour[f] >= 0)
        {
          const Vector2 &n = face_normal[f];
          const double dP = (face_center[f] - cell_center[owner[f]]).dot(n);
          const double dN = (cell_center[neighbour[f]] - face_center[f]).dot(n);
          weight[f] = dN / (dP + dN);
        }
    cell_face_offset.assign(n_cells() + 1, 0);
    for (std::size_t c = 0; c < n_cells(); ++c)
      cell_face_offset[c + 1] = cell_face_offset[c] + cell_faces[c].size();
    gradient_coefficient.resize(cell_face_offset.back());
    cell_face_other.resize(cell_face_offset.back());
    cell_to_face.resize(cell_face_offset.back());
    for (std::size_t c = 0; c < n_cells(); ++c)
      {
        auto other_center = [&](unsigned int f) {
          return neighbour[f] < 0 ? face_center[f] : owner[f] == c ? cell_center[neighbour[f]] : cell_center[owner[f]];
        };
        Eigen::Matrix2d G = Eigen::Matrix2d::Zero();
        for (unsigned int f : cell_faces[c])
          {
            const Vector2 d = other_center(f) - cell_center[c];
            G += d * d.transpose() / d.squaredNorm();
          }
        const Eigen::Matrix2d G_inverse = G.inverse();
        for (std::size_t k = 0; k < cell_faces[c].size(); ++k)
          {
            const Vector2 d = other_center(cell_faces[c][k]) - cell_center[c];
            gradient_coefficient[cell_face_offset[c] + k] = G_inverse * d / d.squaredNorm();
            const unsigned int f = cell_faces[c][k];
            cell_to_face[cell_face_offset[c] + k] = face_center[f] - cell_center[c];
            cell_face_other[cell_face_offset[c] + k] =
              neighbour[f] < 0 ? -int(f) - 1 : owner[f] == c ? neighbour[f] : int(owner[f]);
          }
      }
  }

  int FvMesh::patch_index(const std::string &name) const
  {
    for (std::size_t k = 0; k < patch_names.size(); ++k)
      if (patch_names[k] == name)
        return static_cast<int>(k);
    return -1;
  }

  std::vector<Vector2> FvMesh::gradient(const std::vector<double> &phi, const std::vector<double> &boundary_value) const
  {
    std::vector<Vector2> g;
    gradient(phi, boundary_value, g);
    return g;
  }

  void FvMesh::gradient(const std::vector<double> &phi, const std::vector<double> &boundary_value,
                        std::vector<Vector2> &g) const
  {
    g.resize(n_cells());
    for (std::size_t c = 0; c < n_cells(); ++c)
      {
        Vector2 sum = Vector2::Zero();
        for (std::size_t k = cell_face_offset[c]; k < cell_face_offset[c + 1]; ++k)
          sum += gradient_coefficient[k] * (value_across(k, phi, boundary_value) - phi[c]);
        g[c] = sum;
      }
  }

} // namespace servodrift::flow
