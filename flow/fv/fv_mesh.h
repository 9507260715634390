#pragma once
// The finite-volume mesh of the flow solver: cells (triangles and quadrilaterals from gmsh), faces
// with owner/neighbour addressing, and the geometry of a planar or an axisymmetric (x axial, r = y
// radial) domain. Axisymmetric volumes and face areas are per radian: V = int r dA, S = int r ds.
#include "common/gmsh_mesh.h"

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace servodrift::flow
{
  using Vector2 = Eigen::Vector2d;

  /// A positive floor for denominators that can vanish (a sum of magnitudes, a length scale, a
  /// throughput): far below any value the flow can have, far above the smallest normal double.
  constexpr double vanishing = 1e-300;

  enum class Geometry
  {
    planar,       ///< unit depth
    axisymmetric, ///< x axial, y = r radial; per radian
  };

  class FvMesh
  {
  public:
    /// From a gmsh mesh whose physical curves name the boundaries. Every boundary edge must belong
    /// to a named curve; throws InputError naming `source' otherwise.
    FvMesh(const PlanarMesh &mesh, Geometry geometry, std::string source);

    Geometry geometry;
    std::string source; ///< file or template, for messages

    std::vector<Vector2> points;

    // cells
    std::size_t n_cells() const { return cell_center.size(); }
    std::vector<std::array<unsigned int, 4>> cell_points;
    std::vector<unsigned int> cell_n_points;
    std::vector<Vector2> cell_center; ///< centroid of the 2D cell
    std::vector<double> cell_volume;  ///< area (planar) or int r dA (axisymmetric) [m^2 or m^3/rad]
    std::vector<std::vector<unsigned int>> cell_faces;
    /// The same flattened, for the loops that run several times per iteration (gradients, limiter):
    /// cell c's faces are cell_faces[c][k - cell_face_offset[c]] for k in [cell_face_offset[c],
    /// cell_face_offset[c + 1]), and across face k lies cell_face_other[k]: the neighbour cell
    /// (>= 0) or, on the boundary face f, -(f + 1); cell_to_face[k] is the face's centre minus the
    /// cell's.
    std::vector<std::size_t> cell_face_offset;
    std::vector<int> cell_face_other;
    std::vector<Vector2> cell_to_face;
    /// The value across flattened cell face k: the other cell's, or the boundary face's.
    double value_across(std::size_t k, const std::vector<double> &cell_value,
                        const std::vector<double> &boundary_value) const
    {
      const int other = cell_face_other[k];
      return other >= 0 ? cell_value[std::size_t(other)] : boundary_value[std::size_t(-other - 1)];
    }

    // faces
    std::size_t n_faces() const { return owner.size(); }
    std::vector<unsigned int> owner;
    std::vector<int> neighbour; ///< -1 on the boundary
    std::vector<std::array<unsigned int, 2>> face_points;
    std::vector<Vector2> face_center;
    std::vector<Vector2> face_normal; ///< unit, pointing out of the owner
    std::vector<double> face_area;    ///< length (planar) or int r ds (axisymmetric)
    std::vector<int> face_patch;      ///< boundary patch, -1 inside
    double face_weight(std::size_t f) const { return weight[f]; } ///< owner's share of linear interpolation
    /// Linear interpolation of a cell field to the interior face f: w phi_P + (1 - w) phi_N.
    template <typename T>
    T interpolate(std::size_t f, const std::vector<T> &field) const
    {
      const double w = weight[f];
      return w * field[owner[f]] + (1 - w) * field[std::size_t(neighbour[f])];
    }
    /// n . d of the interior face f: the normal distance between its owner's and its neighbour's
    /// centres (d from owner to neighbour).
    double normal_distance(std::size_t f) const
    {
      return face_normal[f].dot(cell_center[std::size_t(neighbour[f])] - cell_center[owner[f]]);
    }
    /// The normal distance from the owner's centre to the face (the one-sided difference of a
    /// boundary face).
    double distance_to_face(std::size_t f) const
    {
      return (face_center[f] - cell_center[owner[f]]).dot(face_normal[f]);
    }

    /// The face loops, in face order: interior(f, P, N) for a face between owner P and neighbour N,
    /// boundary(f, P) for a boundary face of P. One loop over both kinds where a cell's sums collect
    /// from both, so that they add up in the same order whatever the kind of each face.
    template <typename Interior, typename Boundary>
    void for_each_face(Interior &&interior, Boundary &&boundary) const
    {
      for (std::size_t f = 0; f < n_faces(); ++f)
        if (neighbour[f] >= 0)
          interior(f, owner[f], static_cast<unsigned int>(neighbour[f]));
        else
          boundary(f, owner[f]);
    }
    template <typename Interior>
    void for_each_interior_face(Interior &&interior) const
    {
      for (std::size_t f = 0; f < n_faces(); ++f)
        if (neighbour[f] >= 0)
          interior(f, owner[f], static_cast<unsigned int>(neighbour[f]));
    }
    template <typename Boundary>
    void for_each_boundary_face(Boundary &&boundary) const
    {
      for (std::size_t f = 0; f < n_faces(); ++f)
        if (neighbour[f] < 0)
          boundary(f, owner[f]);
    }

    // boundary patches (gmsh physical curves)
    std::vector<std::string> patch_names;
    std::vector<std::vector<unsigned int>> patch_faces;
    int patch_index(const std::string &name) const; ///< -1 if absent

    /// Least-squares gradient of a cell field; `boundary_value[f]' gives the value at boundary face f.
    std::vector<Vector2> gradient(const std::vector<double> &cell_value, const std::vector<double> &boundary_value) const;
    void gradient(const std::vector<double> &cell_value, const std::vector<double> &boundary_value,
                  std::vector<Vector2> &result) const;
    /// The least-squares coefficients of `gradient' per flattened cell face (k as in cell_face_other):
    /// grad phi_c = sum_k coefficient_k (phi across k - phi_c). The coupled solver's implicit pressure gradient.
    const std::vector<Vector2> &gradient_coefficients() const { return gradient_coefficient; }

  private:
    std::vector<double> weight;
    /// Weighted least squares (weights 1/|d|^2): grad phi_c = sum over the cell's faces of
    /// coefficient * (phi_other - phi_c), coefficient = (sum w d d^T)^-1 w d, stored per cell face.
    std::vector<Vector2> gradient_coefficient; ///< aligned with the flattened cell_faces
  };
} // namespace servodrift::flow
