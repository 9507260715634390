#include "flow/fv/rhie_chow.h"

namespace servodrift::flow
{
  std::vector<double> rhie_chow_fluxes(const FvMesh &mesh, double rho, const FlowState &s,
                                       const std::vector<double> &D, const BoundaryConditions &boundaries)
  {
    using Kind = BoundaryCondition::Kind;
    std::vector<double> F(mesh.n_faces(), 0.0);
    mesh.for_each_face(
      [&](std::size_t f, unsigned int P, unsigned int N) {
        const Vector2 d = mesh.cell_center[N] - mesh.cell_center[P];
        const Vector2 u_f(mesh.interpolate(f, s.u), mesh.interpolate(f, s.v));
        // the mean velocity's flux less D_f times the compact pressure difference minus the mean gradient's
        const double pressure_difference = (s.p[N] - s.p[P]) - mesh.interpolate(f, s.grad_p).dot(d);
        F[f] = rho * (u_f.dot(mesh.face_normal[f]) * mesh.face_area[f] - face_coefficient(mesh, f, D, pressure_difference));
      },
      [&](std::size_t f, unsigned int P) {
        const Vector2 &nrm = mesh.face_normal[f];
        const double area = mesh.face_area[f];
        switch (boundaries.kind(f))
          {
            case Kind::velocity_inlet: F[f] = s.flux[f]; break;
            case Kind::pressure_outlet:
            case Kind::total_pressure_inlet:
              {
                const Vector2 d = mesh.face_center[f] - mesh.cell_center[P];
                const Vector2 uP(s.u[P], s.v[P]);
                const double pressure_difference = (s.p_b[f] - s.p[P]) - s.grad_p[P].dot(d);
                F[f] = rho * (uP.dot(nrm) * area - face_coefficient(mesh, f, D, pressure_difference));
                break;
              }
            default: F[f] = 0; // walls, axis, symmetry
          }
      });
    return F;
  }

  void add_time_step_correction(const FvMesh &mesh, double rho, const TimeLevel &time, const std::vector<double> &D,
                                const std::vector<double> &mixture, const BoundaryConditions &boundaries,
                                std::vector<double> &F)
  {
    // rho m D/dt per cell, the share of the time term in the cell's diagonal (at most 1/w_new), and
    // interpolated as one: across a cavity's edge m and D each change a thousandfold in opposite
    // directions, and the product of their separate interpolations exceeded 1 there and drove the
    // steady cavitating null unstable
    std::vector<double> share(mesh.n_cells());
    for (std::size_t c = 0; c < share.size(); ++c)
      share[c] = rho * mixture[c] * D[c] / time.dt;
    auto old_levels = [&](std::size_t f, double share_f, const auto &velocity_at_face) {
      double sum = 0;
      for (const auto &[level, weight] : {std::pair{&time.last, time.last_weight()}, std::pair{&time.before, time.before_weight()}})
        if (!level->u.empty())
          sum += weight * share_f * (level->flux[f] - rho * velocity_at_face(*level).dot(mesh.face_normal[f]) * mesh.face_area[f]);
      return sum;
    };
    mesh.for_each_face(
      [&](std::size_t f, unsigned int, unsigned int) {
        F[f] += old_levels(f, mesh.interpolate(f, share), [&](const TimeLevelFields &level) {
          return Vector2(mesh.interpolate(f, level.u), mesh.interpolate(f, level.v));
        });
      },
      [&](std::size_t f, unsigned int P) {
        if (boundaries.is_pressure_boundary(f))
          F[f] += old_levels(f, share[P], [&](const TimeLevelFields &level) { return Vector2(level.u[P], level.v[P]); });
      });
  }
} // namespace servodrift::flow
