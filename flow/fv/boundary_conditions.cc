#include "flow/fv/boundary_conditions.h"

#include "common/error.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace servodrift::flow
{
  using Kind = BoundaryCondition::Kind;

  BoundaryCondition BoundaryCondition::wall(Vector2 moving)
  {
    BoundaryCondition b;
    b.kind = Kind::wall;
    b.velocity = [moving](const Vector2 &) { return moving; };
    return b;
  }

  BoundaryCondition BoundaryCondition::velocity_inlet(std::function<Vector2(const Vector2 &)> profile)
  {
    BoundaryCondition b;
    b.kind = Kind::velocity_inlet;
    b.velocity = std::move(profile);
    return b;
  }

  BoundaryCondition BoundaryCondition::total_pressure_inlet(double p0)
  {
    BoundaryCondition b;
    b.kind = Kind::total_pressure_inlet;
    b.pressure = p0;
    return b;
  }

  BoundaryCondition BoundaryCondition::pressure_outlet(double p)
  {
    BoundaryCondition b;
    b.kind = Kind::pressure_outlet;
    b.pressure = p;
    return b;
  }

  BoundaryCondition BoundaryCondition::axis()
  {
    BoundaryCondition b;
    b.kind = Kind::axis;
    return b;
  }

  BoundaryCondition BoundaryCondition::symmetry()
  {
    BoundaryCondition b;
    b.kind = Kind::symmetry;
    return b;
  }

  BoundaryConditions::BoundaryConditions(const FvMesh &mesh_, const FluidProperties &fluid,
                                         const std::map<std::string, BoundaryCondition> &conditions)
    : mesh(mesh_)
    , density(fluid.density)
  {
    for (const auto &[name, bc] : conditions)
      if (mesh.patch_index(name) < 0)
        {
          std::string known;
          for (const auto &n : mesh.patch_names)
            known += (known.empty() ? "" : ", ") + n;
          throw InputError(mesh.source + ": no boundary `" + name + "' (its boundaries: " + known + ")");
        }
    bool inlet = false, outlet = false, moving_wall = false;
    for (std::size_t k = 0; k < mesh.patch_names.size(); ++k)
      {
        const auto found = conditions.find(mesh.patch_names[k]);
        if (found == conditions.end())
          throw InputError(mesh.source + ": boundary `" + mesh.patch_names[k] + "' has no boundary condition");
        const BoundaryCondition &bc = found->second;
        if (bc.kind == Kind::axis && mesh.geometry != Geometry::axisymmetric)
          throw InputError(mesh.source + ": boundary `" + mesh.patch_names[k] + "' is an axis in a planar domain");
        patch_condition.push_back(bc);
        inlet = inlet || bc.kind == Kind::velocity_inlet || bc.kind == Kind::total_pressure_inlet;
        outlet = outlet || bc.kind == Kind::pressure_outlet;
        if (bc.kind == Kind::wall)
          for (unsigned int f : mesh.patch_faces[k])
            moving_wall = moving_wall || bc.velocity(mesh.face_center[f]).norm() > 0;
        any_pressure_boundary = any_pressure_boundary || is_pressure_kind(bc.kind);
      }
    if (!inlet && !moving_wall)
      throw InputError(mesh.source + ": no inlet (and no moving wall) drives the flow");
    if (inlet && !outlet && !any_pressure_boundary)
      throw InputError(mesh.source + ": the flow has an inlet but no outlet");

    face_kind.assign(mesh.n_faces(), Kind::wall);
    face_velocity.assign(mesh.n_faces(), Vector2::Zero());
    inflow_speed.assign(mesh.n_faces(), 0.0);
    mesh.for_each_boundary_face([&](std::size_t f, unsigned int) {
      const BoundaryCondition &bc = of_face(f);
      face_kind[f] = bc.kind;
      if (bc.kind == Kind::wall || bc.kind == Kind::velocity_inlet)
        face_velocity[f] = bc.velocity(mesh.face_center[f]);
    });
    std::vector<double> flux(mesh.n_faces(), 0.0);
    set_velocity_inlet_fluxes(flux);
    mesh.for_each_boundary_face([&](std::size_t f, unsigned int) {
      if (face_kind[f] == Kind::velocity_inlet)
        inlet_inflow += std::max(0.0, -flux[f]);
    });
  }

  const BoundaryCondition &BoundaryConditions::of_face(std::size_t f) const
  {
    return patch_condition[mesh.face_patch[f]];
  }

  void BoundaryConditions::set_velocity_inlet_fluxes(std::vector<double> &flux) const
  {
    mesh.for_each_boundary_face([&](std::size_t f, unsigned int) {
      if (face_kind[f] == Kind::velocity_inlet)
        flux[f] = density * face_velocity[f].dot(mesh.face_normal[f]) * mesh.face_area[f];
    });
  }

  int BoundaryConditions::pressure_patch(const std::string &patch) const
  {
    const int k = mesh.patch_index(patch);
    if (k < 0 || !is_pressure_kind(patch_condition[k].kind))
      throw std::invalid_argument("flow: " + mesh.source + ": `" + patch + "' is not a pressure boundary");
    return k;
  }

  double BoundaryConditions::pressure(const std::string &patch) const
  {
    return patch_condition[pressure_patch(patch)].pressure;
  }

  void BoundaryConditions::set_pressure(const std::string &patch, double p)
  {
    patch_condition[pressure_patch(patch)].pressure = p;
  }

  std::vector<std::pair<std::string, double>> BoundaryConditions::pressures() const
  {
    std::vector<std::pair<std::string, double>> list;
    for (std::size_t k = 0; k < patch_condition.size(); ++k)
      if (is_pressure_kind(patch_condition[k].kind))
        list.emplace_back(mesh.patch_names[k], patch_condition[k].pressure);
    return list;
  }

  void BoundaryConditions::set_pressures(const std::vector<std::pair<std::string, double>> &list)
  {
    for (const auto &[name, p] : list)
      {
        const int k = mesh.patch_index(name);
        if (k >= 0 && is_pressure_kind(patch_condition[k].kind))
          patch_condition[k].pressure = p;
      }
  }

  void BoundaryConditions::scale(double s)
  {
    for (auto &bc : patch_condition)
      bc.pressure *= s;
    const double root = std::sqrt(s);
    for (double &speed : inflow_speed)
      speed *= root;
  }

  void BoundaryConditions::update_inflow_speeds(const std::vector<double> &flux)
  {
    mesh.for_each_boundary_face([&](std::size_t f, unsigned int) {
      if (is_pressure_boundary(f))
        inflow_speed[f] = std::min(flux[f], 0.0) / (density * mesh.face_area[f]);
    });
  }

  void BoundaryConditions::update_values(FlowState &s, double pressure_floor) const
  {
    mesh.for_each_boundary_face([&](std::size_t f, unsigned int P) {
      const Vector2 &n = mesh.face_normal[f];
      const Vector2 uP(s.u[P], s.v[P]);
      Vector2 ub;
      switch (face_kind[f])
        {
          case Kind::wall:
          case Kind::velocity_inlet: ub = face_velocity[f]; break;
          case Kind::symmetry: ub = uP - uP.dot(n) * n; break;
          case Kind::axis: ub = Vector2(s.u[P], 0.0); break;
          default: // pressure boundaries
            // outflow: zero gradient; inflow: normal to the face with the speed of its flux (a
            // zero gradient at an inflow would leave the cell's momentum equation without its
            // convective diagonal and the iteration unstable)
            ub = inflow_speed[f] < 0 ? Vector2(inflow_speed[f] * n) : uP;
        }
      s.u_b[f] = ub.x(), s.v_b[f] = ub.y();
      if (is_pressure_boundary(f))
        {
          // Inflow comes from a reservoir at rest at the given pressure, through a total-pressure
          // inlet or back in through an outlet (entrainment): p = p_0 - rho u_n^2/2 with the
          // face's normal velocity from its flux, the form the pressure correction linearises.
          // Outflow leaves at the given static pressure.
          const double u_n = inflow_speed[f];
          s.p_b[f] = of_face(f).pressure - 0.5 * density * u_n * u_n;
        }
      else // extrapolated with the last gradient (second order at walls: the wall pressure force)
        s.p_b[f] = std::max(s.p[P] + s.grad_p[P].dot(mesh.face_center[f] - mesh.cell_center[P]), pressure_floor);
    });
  }
} // namespace servodrift::flow
