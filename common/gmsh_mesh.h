#pragma once
// Planar meshes from gmsh, through the gmsh SDK: parametric templates (.geo text with ONELAB
// parameters, meshed at run time) and mesh or geometry files (.msh, .geo). The result is a plain
// description, no solver types: the FEM (deal.II) and FV (flow/) codes build their own meshes from it.
#include <array>
#include <map>
#include <string>
#include <vector>

namespace servodrift
{
  struct PlanarMesh
  {
    struct Cell
    {
      std::array<unsigned int, 4> vertices; ///< counterclockwise; a triangle uses the first three
      unsigned int n_vertices;              ///< 3 or 4
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
    std::map<int, std::string> material_names; ///< id -> physical surface name
    std::map<int, std::string> boundary_names; ///< id -> physical curve name
  };

  struct GmshTemplate
  {
    std::string name;      ///< for messages, e.g. "meshes/torque_motor.geo"
    std::string geo_text;  ///< the .geo file
    double unit = 1;       ///< length of one .geo unit [m] (templates are in mm: 1e-3)
    std::string entries;   ///< the subsection whose entries set the geometry ("Torque motor"), for messages
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

  /// A 2D mesh of triangles and quadrilaterals: a template meshed with `parameters' (as above), where
  /// every physical surface becomes a material and every physical curve a boundary, numbered from 0
  /// in the order of their names, which are recorded.
  PlanarMesh mesh_template_all_groups(const GmshTemplate &geo, const std::map<std::string, double> &parameters);

  /// The same from a file: a .msh mesh (read as is) or a .geo geometry (meshed in 2D). Throws
  /// InputError naming the file if it does not exist or is not a gmsh file, or holds no 2D cells.
  PlanarMesh read_gmsh_file(const std::string &path, double unit = 1);
} // namespace servodrift
