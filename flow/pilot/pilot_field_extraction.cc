// What a pilot-stage case's fields give (model.md 4.2): Q, C_d, Re, the forces and the diagnostics.
#include "flow/pilot/pilot_field_extraction.h"

#include "common/pilot_closed_forms.h"
#include "common/units.h"

#include <algorithm>
#include <cmath>

namespace servodrift::flow
{
  double ideal_velocity(double dp, double rho) { return std::sqrt(2 * dp / rho); }

  PilotFieldResult extract_pilot_result(const SimplecSolver &solver, const FvMesh &mesh, const PilotCaseShape &shape,
                                        const PilotFieldCase &conditions, double vapour_pressure,
                                        double downstream, double dp, MeteredAt metered)
  {
    PilotFieldResult r;
    const double rho = conditions.fluid.density, mu = conditions.fluid.viscosity;
    const double v_ideal = ideal_velocity(dp, rho);
    r.pressure_difference = dp;
    r.turbulence = conditions.turbulence;
    // (a patch's flow rate is out of the domain: the inlet's is negative)
    r.flow_rate = metered == MeteredAt::outlet ? solver.flow_rate("outlet") : -solver.flow_rate("inlet");
    r.minimum_pressure = solver.minimum_pressure();
    r.minimum_absolute_pressure = downstream + r.minimum_pressure;
    const auto gamma = solver.liquid_fraction();
    r.cavitating = *std::min_element(gamma.begin(), gamma.end()) < 1 ||
                   r.minimum_absolute_pressure < vapour_pressure * (1 - 1e-9);
    const auto y_plus = solver.wall_y_plus();
    r.max_wall_y_plus = *std::max_element(y_plus.begin(), y_plus.end());
    for (const double mu_t : solver.turbulent_viscosity())
      r.max_turbulent_viscosity_ratio = std::max(r.max_turbulent_viscosity_ratio, mu_t / mu);

    if (shape.kind == PilotGeometry::fixed_orifice)
      {
        const double area = units::pi * shape.bore_radius * shape.bore_radius;
        r.discharge_coefficient = r.flow_rate / (area * v_ideal);
        r.reynolds_number = 2 * shape.bore_radius * v_ideal * rho / mu; // E17
        return r;
      }
    const double D_N = 2 * shape.bore_radius, h = shape.gap;
    r.discharge_coefficient = r.flow_rate / (units::pi * D_N * h * v_ideal); // curtain area (4.2)
    r.reynolds_number = nozzle_reynolds_number(D_N, h, r.discharge_coefficient, v_ideal, mu / rho); // E18
    const Vector2 axial(1, 0);
    r.flapper_force = solver.pressure_force("flapper", axial);
    r.land_force = solver.pressure_force("land", -axial);
    // the bore's exit plane: mean pressure and axial momentum (p + rho u_x^2) through it
    double sum = 0, area = 0, momentum = 0;
    const auto &p = solver.pressure();
    const auto &u = solver.velocity_x();
    const auto &F = solver.mass_flux();
    for (unsigned int f : shape.exit_faces)
      {
        const double p_f = mesh.interpolate(f, p), u_f = mesh.interpolate(f, u);
        sum += p_f * mesh.face_area[f];
        area += mesh.face_area[f];
        // F n_x = rho u_x A: the +x momentum flux rho u_x^2 A
        momentum += p_f * mesh.face_area[f] + F[f] * mesh.face_normal[f].x() * u_f;
      }
    r.bore_pressure = sum / area;
    r.jet_force = 2 * units::pi * momentum;
    return r;
  }
} // namespace servodrift::flow
