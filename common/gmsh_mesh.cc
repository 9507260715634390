#include "common/gmsh_mesh.h"

#include "common/error.h"

#include <gmsh.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unordered_map>

// gmsh 4.8's .geo lexer keeps the unread rest of a file with a syntax error and feeds it to the
// next file parsed, even across gmsh::finalize (every later template then fails). It exports the
// function that flushes it, though its API does not declare it.
void gmsh_yyflush();

namespace servodrift
{
  namespace
  {
    /// gmsh holds global state: one session at a time, always finalised.
    struct GmshSession
    {
      GmshSession()
      {
        gmsh::initialize(0, nullptr, false);
        gmsh::option::setNumber("General.Terminal", 0);
        gmsh::option::setNumber("General.Verbosity", 1);
        gmsh::option::setNumber("General.NumThreads", 1);
        gmsh::option::setNumber("Mesh.MaxNumThreads2D", 1);
        gmsh::onelab::clear(); // no parameter of an earlier template may leak into this one
        gmsh::logger::start();
      }
      ~GmshSession()
      {
        gmsh::logger::stop();
        gmsh::finalize();
      }
      /// gmsh's messages that start with "Error", joined; also leaves the parser clean for the next file.
      std::string last_errors()
      {
        gmsh_yyflush();
        std::vector<std::string> log;
        gmsh::logger::get(log);
        std::string errors;
        for (const auto &line : log)
          if (line.rfind("Error", 0) == 0)
            errors += (errors.empty() ? "" : "; ") + line;
        return errors;
      }
    };

    std::vector<int> physical_entities(int dim, const std::string &name, const std::string &source)
    {
      gmsh::vectorpair groups;
      gmsh::model::getPhysicalGroups(groups, dim);
      for (const auto &[d, tag] : groups)
        {
          std::string n;
          gmsh::model::getPhysicalName(d, tag, n);
          if (n == name)
            {
              std::vector<int> entities;
              gmsh::model::getEntitiesForPhysicalGroup(d, tag, entities);
              return entities;
            }
        }
      throw std::runtime_error(source + ": no physical group `" + name + "'");
    }

    std::vector<std::string> physical_names(int dim)
    {
      gmsh::vectorpair groups;
      gmsh::model::getPhysicalGroups(groups, dim);
      std::vector<std::string> names;
      for (const auto &[d, tag] : groups)
        {
          std::string n;
          gmsh::model::getPhysicalName(d, tag, n);
          names.push_back(n.empty() ? std::to_string(tag) : n);
        }
      std::sort(names.begin(), names.end());
      return names;
    }

    /// The current gmsh model as a PlanarMesh: cells of the named surfaces, faces of the named curves.
    PlanarMesh extract(const std::string &source, double unit, const std::map<std::string, int> &materials,
                       const std::map<std::string, int> &boundaries, bool allow_triangles)
    {
      PlanarMesh mesh;
      std::vector<std::size_t> node_tags;
      std::vector<double> coordinates, parametric;
      gmsh::model::mesh::getNodes(node_tags, coordinates, parametric);
      std::unordered_map<std::size_t, unsigned int> index;
      for (std::size_t k = 0; k < node_tags.size(); ++k)
        {
          index[node_tags[k]] = static_cast<unsigned int>(mesh.vertices.size());
          mesh.vertices.push_back({coordinates[3 * k] * unit, coordinates[3 * k + 1] * unit});
        }
      std::vector<int> types;
      gmsh::model::mesh::getElementTypes(types, 2);
      for (int t : types)
        if (t != 3 && !(t == 2 && allow_triangles))
          throw std::runtime_error(source + ": the mesh has elements of gmsh type " + std::to_string(t) + "; only " +
                                   (allow_triangles ? "3-node triangles and " : "") + "4-node quadrilaterals can be used");

      std::map<int, std::string> owner; // every surface in one material group only
      for (const auto &[name, material] : materials)
        {
          mesh.material_names[material] = name;
          for (int entity : physical_entities(2, name, source))
            {
              if (!owner.emplace(entity, name).second)
                throw std::runtime_error(source + ": surface " + std::to_string(entity) + " is in both `" +
                                         owner[entity] + "' and `" + name + "'");
              for (int type : {2, 3})
                {
                  const unsigned int n = type == 2 ? 3 : 4;
                  std::vector<std::size_t> element_tags, element_nodes;
                  gmsh::model::mesh::getElementsByType(type, element_tags, element_nodes, entity);
                  for (std::size_t e = 0; e < element_tags.size(); ++e)
                    {
                      PlanarMesh::Cell c{{0, 0, 0, 0}, n, material};
                      for (unsigned int v = 0; v < n; ++v)
                        c.vertices[v] = index.at(element_nodes[n * e + v]);
                      mesh.cells.push_back(c);
                    }
                }
            }
        }
      for (const auto &[name, boundary] : boundaries)
        {
          mesh.boundary_names[boundary] = name;
          for (int entity : physical_entities(1, name, source))
            {
              std::vector<std::size_t> element_tags, element_nodes;
              gmsh::model::mesh::getElementsByType(1, element_tags, element_nodes, entity);
              for (std::size_t e = 0; e < element_tags.size(); ++e)
                mesh.boundary_faces.push_back(
                  {{index.at(element_nodes[2 * e]), index.at(element_nodes[2 * e + 1])}, boundary});
            }
        }
      // counterclockwise, whatever the orientation of the gmsh surface
      for (auto &c : mesh.cells)
        {
          double area = 0;
          for (unsigned int v = 0; v < c.n_vertices; ++v)
            {
              const auto &a = mesh.vertices[c.vertices[v]], &b = mesh.vertices[c.vertices[(v + 1) % c.n_vertices]];
              area += a[0] * b[1] - b[0] * a[1];
            }
          if (area < 0)
            std::swap(c.vertices[1], c.vertices[c.n_vertices - 1]);
        }
      return mesh;
    }

    /// Writes the template to a private temporary file (gmsh reads files), runs `work', removes it.
    template <typename Work>
    PlanarMesh with_template_file(const GmshTemplate &geo, const std::map<std::string, double> &parameters, Work &&work)
    {
      const std::string file = (std::filesystem::temp_directory_path() /
                                ("servodrift-" + std::to_string(::getpid()) + "-" +
                                 std::filesystem::path(geo.name).filename().string()))
                                 .string();
      std::ofstream(file) << geo.geo_text;
      GmshSession session;
      try
        {
          for (const auto &[key, value] : parameters)
            gmsh::onelab::setNumber("Parameters/" + key, {value});
          gmsh::open(file);
          gmsh::model::mesh::generate(2);
        }
      catch (...)
        {
          std::remove(file.c_str());
          const std::string errors = session.last_errors();
          throw InputError((geo.entries.empty() ? geo.name + ": gmsh could not mesh the geometry" :
                                                  "the `" + geo.entries + "' entries give a geometry that gmsh cannot "
                                                  "mesh (" + geo.name + "; parts overlap or touch? check the "
                                                  "dimensions changed)") +
                           (errors.empty() ? std::string() : ": " + errors.substr(0, 160)));
        }
      std::remove(file.c_str());
      return work();
    }

    std::map<std::string, int> numbered(const std::vector<std::string> &names)
    {
      std::map<std::string, int> m;
      for (std::size_t k = 0; k < names.size(); ++k)
        m[names[k]] = static_cast<int>(k);
      return m;
    }
  } // namespace

  PlanarMesh mesh_template(const GmshTemplate &geo, const std::map<std::string, double> &parameters,
                           const std::map<std::string, int> &materials, const std::map<std::string, int> &boundaries,
                           bool mirror_x, const std::map<int, int> &mirrored_materials)
  {
    PlanarMesh mesh = with_template_file(geo, parameters, [&] {
      return extract(geo.name, geo.unit, materials, boundaries, /*allow_triangles=*/false);
    });
    if (mirror_x)
      {
        // Mirror about x = 0; nodes on the axis (x = 0 exactly: they lie on straight axis curves)
        // are shared, so the two halves are one conforming mesh, exactly symmetric.
        const std::size_t n = mesh.vertices.size();
        std::vector<unsigned int> mirror(n);
        for (std::size_t k = 0; k < n; ++k)
          if (mesh.vertices[k][0] == 0.0)
            mirror[k] = static_cast<unsigned int>(k);
          else
            {
              mirror[k] = static_cast<unsigned int>(mesh.vertices.size());
              mesh.vertices.push_back({-mesh.vertices[k][0], mesh.vertices[k][1]});
            }
        const std::size_t n_cells = mesh.cells.size(), n_faces = mesh.boundary_faces.size();
        for (std::size_t c = 0; c < n_cells; ++c)
          {
            PlanarMesh::Cell m = mesh.cells[c];
            for (auto &v : m.vertices)
              v = mirror[v];
            std::swap(m.vertices[1], m.vertices[3]); // mirroring reverses the orientation
            const auto other = mirrored_materials.find(m.material);
            if (other != mirrored_materials.end())
              m.material = other->second;
            mesh.cells.push_back(m);
          }
        for (std::size_t f = 0; f < n_faces; ++f)
          {
            PlanarMesh::Face m = mesh.boundary_faces[f];
            m.vertices = {mirror[m.vertices[1]], mirror[m.vertices[0]]};
            mesh.boundary_faces.push_back(m);
          }
      }
    return mesh;
  }

  PlanarMesh mesh_template_all_groups(const GmshTemplate &geo, const std::map<std::string, double> &parameters)
  {
    return with_template_file(geo, parameters, [&] {
      return extract(geo.name, geo.unit, numbered(physical_names(2)), numbered(physical_names(1)), true);
    });
  }

  PlanarMesh read_gmsh_file(const std::string &path, double unit)
  {
    if (!std::filesystem::is_regular_file(path))
      throw InputError(path + ": no such mesh file");
    const std::string extension = std::filesystem::path(path).extension().string();
    if (extension != ".msh" && extension != ".geo")
      throw InputError(path + ": not a gmsh file (use a .msh mesh or a .geo geometry)");
    if (extension == ".msh")
      {
        std::string first_line;
        std::getline(std::ifstream(path), first_line);
        if (first_line.rfind("$MeshFormat", 0) != 0)
          throw InputError(path + ": not a gmsh mesh (a .msh file starts with $MeshFormat)");
      }
    GmshSession session;
    try
      {
        gmsh::open(path);
        if (extension == ".geo")
          gmsh::model::mesh::generate(2);
      }
    catch (...)
      {
        const std::string errors = session.last_errors();
        throw InputError(path + ": gmsh cannot read it" + (errors.empty() ? std::string() : " (" + errors + ")"));
      }
    PlanarMesh mesh = extract(path, unit, numbered(physical_names(2)), numbered(physical_names(1)), true);
    if (mesh.cells.empty())
      throw InputError(path + ": no 2D cells in physical surfaces (name the domain with a Physical Surface)");
    return mesh;
  }
} // namespace servodrift
