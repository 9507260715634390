#include "flow/fv/flow_postprocessing.h"

#include "common/units.h"
#include "flow/fv/continuity.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace servodrift::flow
{
  const std::vector<unsigned int> &patch_faces(const FvMesh &mesh, const std::string &patch)
  {
    const int k = mesh.patch_index(patch);
    if (k < 0)
      throw std::invalid_argument("flow: no boundary `" + patch + "' in " + mesh.source);
    return mesh.patch_faces[k];
  }

  double revolution(const FvMesh &mesh) { return mesh.geometry == Geometry::axisymmetric ? 2 * units::pi : 1.0; }

  double flow_rate(const FvMesh &mesh, const std::vector<double> &mass_flux, double density, const std::string &patch)
  {
    double q = 0;
    for (unsigned int f : patch_faces(mesh, patch))
      q += mass_flux[f];
    return q / density * revolution(mesh);
  }

  double mean_pressure(const FvMesh &mesh, const std::vector<double> &p_b, const std::string &patch)
  {
    double sum = 0, area = 0;
    for (unsigned int f : patch_faces(mesh, patch))
      {
        sum += p_b[f] * mesh.face_area[f];
        area += mesh.face_area[f];
      }
    return area > 0 ? sum / area : 0.0;
  }

  double mean_total_pressure(const FvMesh &mesh, const FlowState &s, const std::vector<double> &mass_flux,
                             double density, const std::string &patch)
  {
    double sum = 0, flow = 0;
    for (unsigned int f : patch_faces(mesh, patch))
      {
        const double weight = std::abs(mass_flux[f]);
        sum += weight * (s.p_b[f] + 0.5 * density * (s.u_b[f] * s.u_b[f] + s.v_b[f] * s.v_b[f]));
        flow += weight;
      }
    return flow > 0 ? sum / flow : mean_pressure(mesh, s.p_b, patch);
  }

  double minimum_pressure(const FvMesh &mesh, const FlowState &s)
  {
    double lowest = *std::min_element(s.p.begin(), s.p.end());
    mesh.for_each_boundary_face([&](std::size_t f, unsigned int) { lowest = std::min(lowest, s.p_b[f]); });
    return lowest;
  }

  double pressure_force(const FvMesh &mesh, const std::vector<double> &p_b, const std::string &patch,
                        const Vector2 &direction, double p_reference)
  {
    double F = 0;
    for (unsigned int f : patch_faces(mesh, patch))
      F += (p_b[f] - p_reference) * mesh.face_normal[f].dot(direction) * mesh.face_area[f];
    return F * revolution(mesh);
  }

  std::vector<double> wall_y_plus(const FvMesh &mesh, const FlowState &s, const BoundaryConditions &boundaries,
                                  const FluidProperties &fluid)
  {
    std::vector<double> y_plus(mesh.n_cells(), 0.0);
    const double rho = fluid.density, mu = fluid.viscosity;
    mesh.for_each_boundary_face([&](std::size_t f, unsigned int P) {
      if (boundaries.kind(f) != BoundaryCondition::Kind::wall)
        return;
      const Vector2 &n = mesh.face_normal[f];
      Vector2 relative = Vector2(s.u[P], s.v[P]) - boundaries.prescribed_velocity(f);
      relative -= relative.dot(n) * n; // tangential
      const double distance = mesh.distance_to_face(f);
      const double tau = mu * relative.norm() / distance;
      y_plus[P] = std::max(y_plus[P], std::sqrt(tau * rho) * distance / mu);
    });
    return y_plus;
  }

  double throughput(const FvMesh &mesh, const std::vector<double> &mass_flux)
  {
    double inflow = 0;
    mesh.for_each_boundary_face([&](std::size_t f, unsigned int) { inflow += std::max(0.0, -mass_flux[f]); });
    return inflow;
  }

  double max_cell_imbalance(const FvMesh &mesh, const std::vector<double> &flux, const CavitationModel &cavitation)
  {
    double largest = 0;
    for (double m : cell_mass_imbalance(mesh, flux, cavitation))
      largest = std::max(largest, std::abs(m));
    return largest / std::max(throughput(mesh, cavitation.convecting_flux(flux)), vanishing);
  }

  double net_imbalance(const FvMesh &mesh, const std::vector<double> &mass_flux)
  {
    double net = 0;
    mesh.for_each_boundary_face([&](std::size_t f, unsigned int) { net += mass_flux[f]; });
    return std::abs(net) / std::max(throughput(mesh, mass_flux), vanishing);
  }
} // namespace servodrift::flow
