#include "magnetics/gmsh_mesh.h"

#include <gmsh.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unordered_map>

namespace servodrift::magnetics
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
      std::string last_errors()
      {
        std::vector<std::string> log;
        gmsh::logger::get(log);
        std::string errors;
        for (const auto &line : log)
          if (line.rfind("Error", 0) == 0)
            errors += (errors.empty() ? "" : "; ") + line;
        return errors;
      }
    };
  } // namespace

  PlanarMesh mesh_template(const GmshTemplate &geo, const std::map<std::string, double> &parameters,
                           const std::map<std::string, int> &materials, const std::map<std::string, int> &boundaries,
                           bool mirror_x, const std::map<int, int> &mirrored_materials)
  {
    // gmsh reads templates from files: a private temporary copy
    const std::string file = (std::filesystem::temp_directory_path() /
                              ("servodrift-" + std::to_string(::getpid()) + "-" +
                               std::filesystem::path(geo.name).filename().string()))
                               .string();
    std::ofstream(file) << geo.geo_text;

    GmshSession session;
    PlanarMesh mesh;
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
        throw std::runtime_error(geo.name + ": gmsh could not mesh the geometry" +
                                 (errors.empty() ? std::string() : ": " + errors));
      }
    std::remove(file.c_str());

    std::vector<std::size_t> node_tags;
    std::vector<double> coordinates, parametric;
    gmsh::model::mesh::getNodes(node_tags, coordinates, parametric);
    std::unordered_map<std::size_t, unsigned int> index;
    for (std::size_t k = 0; k < node_tags.size(); ++k)
      {
        index[node_tags[k]] = static_cast<unsigned int>(mesh.vertices.size());
        mesh.vertices.push_back({coordinates[3 * k] * geo.unit, coordinates[3 * k + 1] * geo.unit});
      }

    std::vector<int> types;
    gmsh::model::mesh::getElementTypes(types, 2);
    for (int t : types)
      if (t != 3)
        throw std::runtime_error(geo.name + ": the mesh has elements of gmsh type " + std::to_string(t) +
                                 "; only 4-node quadrilaterals can be used");

    auto physical = [&](int dim, const std::string &name) {
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
      throw std::runtime_error(geo.name + ": no physical group `" + name + "'");
    };

    std::map<int, std::string> owner; // every surface in one material group only
    for (const auto &[name, material] : materials)
      for (int entity : physical(2, name))
        {
          if (!owner.emplace(entity, name).second)
            throw std::runtime_error(geo.name + ": surface " + std::to_string(entity) + " is in both `" + owner[entity] +
                                     "' and `" + name + "'");
          std::vector<std::size_t> element_tags, element_nodes;
          gmsh::model::mesh::getElementsByType(3, element_tags, element_nodes, entity);
          for (std::size_t e = 0; e < element_tags.size(); ++e)
            {
              PlanarMesh::Cell c;
              for (int v = 0; v < 4; ++v)
                c.vertices[v] = index.at(element_nodes[4 * e + v]);
              c.material = material;
              mesh.cells.push_back(c);
            }
        }
    for (const auto &[name, boundary] : boundaries)
      for (int entity : physical(1, name))
        {
          std::vector<std::size_t> element_tags, element_nodes;
          gmsh::model::mesh::getElementsByType(1, element_tags, element_nodes, entity);
          for (std::size_t e = 0; e < element_tags.size(); ++e)
            mesh.boundary_faces.push_back({{index.at(element_nodes[2 * e]), index.at(element_nodes[2 * e + 1])}, boundary});
        }

    // gmsh orders a quadrilateral's nodes counterclockwise in its surface's orientation: make sure
    for (auto &c : mesh.cells)
      {
        const auto &p = mesh.vertices;
        double area = 0;
        for (int v = 0; v < 4; ++v)
          {
            const auto &a = p[c.vertices[v]], &b = p[c.vertices[(v + 1) % 4]];
            area += a[0] * b[1] - b[0] * a[1];
          }
        if (area < 0)
          std::swap(c.vertices[1], c.vertices[3]);
      }

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
} // namespace servodrift::magnetics
