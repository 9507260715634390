#pragma once
// Planar quadrilateral meshes from parametric gmsh templates, through the gmsh SDK. The result is a
// plain description (no deal.II types), turned into a deal.II triangulation by the solver.
#include <array>
#include <map>
#include <string>
#include <vector>

namespace servodrift::magnetics
{
  struct PlanarMesh
  {
    struct Cell
    {
      std::array<unsigned int, 4> vertices; ///< counterclockwise
      int material;
    };
    struct Face
    {
      std::array<unsigned int, 2> vertices;
      int boundary;
    };
    std::vector<std::array<double, 2>> vertices; ///< [m]
    std::vector<Cell> cells;
    std::vector<Face> boundary_faces;
  };

  struct GmshTemplate
  {
    std::string name;      ///< for messages, e.g. "meshes/torque_motor.geo"
    std::string geo_text;  ///< the .geo file
    double unit = 1;       ///< length of one .geo unit [m] (templates are in mm: 1e-3)
  };

  /// Meshes `geo' with the ONELAB parameters "Parameters/<key>" set to the given values (in .geo
  /// units). Only quadrilaterals are accepted. Physical surfaces named in `materials' become cell
  /// materials, physical curves named in `boundaries' become boundary faces. With `mirror_x', the
  /// template is a right half and the mesh is mirrored about x = 0 into an exactly symmetric one;
  /// mirrored cells take the material `mirrored_materials[m]' where given (e.g. the other coil).
  /// Throws std::runtime_error naming the template and gmsh's message if meshing fails.
  PlanarMesh mesh_template(const GmshTemplate &geo, const std::map<std::string, double> &parameters,
                           const std::map<std::string, int> &materials, const std::map<std::string, int> &boundaries,
                           bool mirror_x, const std::map<int, int> &mirrored_materials = {});
} // namespace servodrift::magnetics
