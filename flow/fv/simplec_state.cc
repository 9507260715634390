// SimplecSolver: continuation between cases (fields, pressure levels) and the state that Anderson
// acceleration combines.
#include "flow/fv/simplec_implementation.h"

#include "common/error.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace servodrift::flow
{
  void SimplecSolver::scale_pressure_level(double s)
  {
    if (!(s > 0) || !std::isfinite(s))
      throw std::invalid_argument("flow: pressure scaling " + format_number(s) + " must be > 0");
    auto &d = *impl;
    d.forget_time_levels();
    FlowState &state = d.state;
    const double root = std::sqrt(s);
    auto scale = [](std::vector<double> &x, double factor) {
      for (double &value : x)
        value *= factor;
    };
    scale(state.p, s), scale(state.p_b, s);
    for (auto &g : state.grad_p)
      g *= s;
    for (auto *field : {&state.u, &state.v, &state.u_b, &state.v_b, &state.flux})
      scale(*field, root);
    d.boundaries.scale(s);
    d.turbulence->scale_pressure_level(s);
    d.update_boundary_values();
  }

  FlowFields SimplecSolver::fields() const
  {
    const auto &d = *impl;
    FlowFields f;
    f.u = d.state.u, f.v = d.state.v, f.p = d.state.p, f.flux = d.state.flux;
    d.turbulence->store(f);
    f.face_area = d.mesh.face_area;
    f.density = d.fluid.density;
    if (d.cavitation.enabled())
      f.liquid_fraction = d.cavitation.gamma, f.cavitating = d.cavitation.cavitating;
    f.boundary_pressures = d.boundaries.pressures();
    return f;
  }

  void SimplecSolver::set_fields(const FlowFields &o)
  {
    auto &d = *impl;
    d.forget_time_levels();
    const FvMesh &mesh = d.mesh;
    FlowState &s = d.state;
    const bool with_fluxes = !o.flux.empty();
    if (o.u.size() != mesh.n_cells() || (with_fluxes && o.flux.size() != mesh.n_faces()))
      throw std::invalid_argument("flow: " + mesh.source + ": cannot start from the fields of a different mesh");
    s.u = o.u, s.v = o.v, s.p = o.p;
    d.boundaries.set_pressures(o.boundary_pressures);
    if (d.turbulence->turbulent())
      d.turbulence->restore(o);
    const double rho = d.fluid.density;
    for (std::size_t f = 0; f < mesh.n_faces(); ++f)
      {
        if (mesh.neighbour[f] < 0 && d.boundaries.kind(f) == BoundaryCondition::Kind::velocity_inlet)
          continue; // fixed by its condition
        if (with_fluxes) // the face fluxes scale with the face areas of this mesh (same topology, other dimensions)
          // (a face of no area, on the axis, carries none: not 0/0)
          s.flux[f] = o.face_area[f] > 0 ? o.flux[f] * mesh.face_area[f] / o.face_area[f] * rho / o.density : 0.0;
        else // fields carried from another mesh (transfer_fields): fluxes of the face velocities
          {
            const unsigned int P = mesh.owner[f];
            Vector2 u_f(s.u[P], s.v[P]);
            if (mesh.neighbour[f] >= 0)
              u_f = Vector2(mesh.interpolate(f, s.u), mesh.interpolate(f, s.v));
            else if (!d.boundaries.is_pressure_boundary(f))
              u_f.setZero(); // walls, axis, symmetry
            s.flux[f] = rho * u_f.dot(mesh.face_normal[f]) * mesh.face_area[f];
          }
      }
    CavitationModel &cavitation = d.cavitation;
    if (o.liquid_fraction.size() == mesh.n_cells())
      cavitation.gamma = o.liquid_fraction, cavitation.cavitating = o.cavitating;
    else
      std::fill(cavitation.gamma.begin(), cavitation.gamma.end(), 1.0),
        std::fill(cavitation.cavitating.begin(), cavitation.cavitating.end(), 0);
    cavitation.update_mixture_flux(s.flux);
    d.boundaries.update_inflow_speeds(s.flux);
    d.update_boundary_values();
    s.grad_p = mesh.gradient(s.p, s.p_b);
    d.update_boundary_values();
  }

  void SimplecSolver::initialize_from(const SimplecSolver &other) { set_fields(other.fields()); }

  std::vector<std::vector<double> *> SimplecSolver::Implementation::accelerated_fields()
  {
    std::vector<std::vector<double> *> fields{&state.u, &state.v, &state.p, &state.flux};
    for (auto *field : turbulence->accelerated_fields())
      fields.push_back(field);
    if (cavitation.enabled())
      fields.push_back(&cavitation.gamma);
    return fields;
  }

  Eigen::VectorXd SimplecSolver::Implementation::pack()
  {
    const auto fields = accelerated_fields();
    if (field_scales.size() != fields.size())
      {
        field_scales.clear();
        for (const auto *field : fields)
          {
            double largest = 0;
            for (double value : *field)
              largest = std::max(largest, std::abs(value));
            field_scales.push_back(largest > 0 ? largest : 1.0);
          }
      }
    std::size_t size = 0;
    for (const auto *field : fields)
      size += field->size();
    Eigen::VectorXd x(size);
    std::size_t at = 0;
    for (std::size_t j = 0; j < fields.size(); ++j)
      for (double value : *fields[j])
        x[at++] = value / field_scales[j];
    return x;
  }

  /// Writes an accelerated state back, bounded (the turbulence model's fields as it says, 0 <= gamma
  /// <= 1), with what depends on it (mass fluxes, face viscosities, pressure boundaries' inflow speeds).
  void SimplecSolver::Implementation::unpack(const Eigen::VectorXd &x)
  {
    const auto fields = accelerated_fields();
    std::vector<std::vector<double>> turbulence_before;
    for (const auto *field : turbulence->accelerated_fields())
      turbulence_before.push_back(*field);
    std::size_t at = 0;
    for (std::size_t j = 0; j < fields.size(); ++j)
      for (double &value : *fields[j])
        value = x[at++] * field_scales[j];
    if (turbulence->turbulent())
      turbulence->bound_accelerated(turbulence_before);
    if (cavitation.enabled())
      {
        for (double &gamma : cavitation.gamma)
          gamma = std::clamp(gamma, 0.0, 1.0);
        cavitation.update_mixture_flux(state.flux);
      }
    boundaries.update_inflow_speeds(state.flux);
  }
} // namespace servodrift::flow
