#include "flow/pilot_field.h"

#include "common/error.h"
#include "common/gmsh_mesh.h"
#include "common/thermal_laws.h"
#include "common/units.h"

#include <cmath>
#include <map>

namespace servodrift
{
  namespace embedded
  {
    extern const char *const fixed_orifice_geo;
    extern const char *const nozzle_flapper_geo;
  } // namespace embedded
} // namespace servodrift

namespace servodrift::flow
{
  namespace
  {
    constexpr double mm = 1e-3; // the templates are in mm

    laws::PilotStageGeometry geometry_at(const ValveDescription &valve, double T)
    {
      return laws::pilot_stage_geometry(valve.pilot, valve.armature, valve.expansion, T,
                                        valve.operating.reference_temperature);
    }

    /// sqrt(2 dp / rho): the ideal (Bernoulli) velocity of a pressure difference [m/s].
    double ideal_velocity(double dp, double rho) { return std::sqrt(2 * dp / rho); }

    /// Sets the inlet's total pressure dp above the outlet and solves (from the last fields): the
    /// flow rate, the lowest pressure and the iterations of a case, orifice or nozzle alike.
    PilotFieldResult solve_case(SimplecSolver &solver, double dp, const char *what)
    {
      if (!(dp > 0) || !std::isfinite(dp))
        throw InputError(std::string("flow: ") + what + ": pressure difference " + format_number(dp) +
                         " Pa must be > 0");
      // continuation from the last fields, scaled to the new pressure level first
      const double previous = solver.boundary_pressure("inlet");
      if (previous > 0 && previous != dp)
        solver.scale_pressure_level(dp / previous);
      solver.set_boundary_pressure("inlet", dp);
      const SolveReport report = solver.solve();
      PilotFieldResult r;
      r.pressure_difference = dp;
      r.flow_rate = solver.flow_rate("outlet");
      r.minimum_pressure = solver.minimum_pressure();
      r.iterations = report.iterations;
      return r;
    }
  } // namespace

  PilotFieldCase pilot_field_case(const ValveDescription &valve, double T)
  {
    const laws::Oil oil(valve.fluid, valve.operating.reference_temperature);
    return {T, {oil.density(T).value, oil.dynamic_viscosity(T)}, valve.pilot.field_resolution};
  }

  // ---- fixed orifice ---------------------------------------------------------------------------

  struct FixedOrificeField::Implementation
  {
    double bore_radius;
    FluidProperties fluid;
    FvMesh mesh;
    SimplecSolver solver;

    static FvMesh make_mesh(const ValveDescription &valve, const PilotFieldCase &c, double &r0)
    {
      const auto g = geometry_at(valve, c.temperature);
      r0 = 0.5 * g.fixed_orifice_diameter;
      const double l = g.fixed_orifice_length;
      const double plenum = valve.pilot.field_plenum_size * r0;
      const std::map<std::string, double> parameters{
        {"r0", r0 / mm}, {"l", l / mm}, {"ru", plenum / mm}, {"lu", plenum / mm}, {"rd", 8 * r0 / mm},
        {"ld", valve.pilot.field_chamber_length * r0 / mm}, {"res", c.resolution}};
      return FvMesh(mesh_template_all_groups({"meshes/fixed_orifice.geo", embedded::fixed_orifice_geo, mm}, parameters),
                    Geometry::axisymmetric, "meshes/fixed_orifice.geo");
    }

    Implementation(const ValveDescription &valve, const PilotFieldCase &c)
      : fluid(c.fluid)
      , mesh(make_mesh(valve, c, bore_radius))
      , solver(mesh, fluid,
               {{"inlet", BoundaryCondition::total_pressure_inlet(0)},
                {"outlet", BoundaryCondition::pressure_outlet(0)},
                {"wall", BoundaryCondition::wall()},
                {"axis", BoundaryCondition::axis()}},
               valve.flow_solver)
    {}
  };

  FixedOrificeField::FixedOrificeField(const ValveDescription &valve, const PilotFieldCase &c)
    : impl(std::make_unique<Implementation>(valve, c))
  {}
  FixedOrificeField::~FixedOrificeField() = default;

  PilotFieldResult FixedOrificeField::solve(double dp)
  {
    auto &d = *impl;
    PilotFieldResult r = solve_case(d.solver, dp, "fixed orifice");
    const double area = units::pi * d.bore_radius * d.bore_radius, v_ideal = ideal_velocity(dp, d.fluid.density);
    r.discharge_coefficient = r.flow_rate / (area * v_ideal);
    r.reynolds_number = 2 * d.bore_radius * v_ideal * d.fluid.density / d.fluid.viscosity; // E17
    return r;
  }

  void FixedOrificeField::initialize_from(const FixedOrificeField &other) { impl->solver.initialize_from(other.impl->solver); }
  void FixedOrificeField::set_failure_output(const std::string &f) { impl->solver.failure_output = f; }
  void FixedOrificeField::write_vtu(const std::string &filename) const { impl->solver.write_vtu(filename); }
  std::size_t FixedOrificeField::n_cells() const { return impl->mesh.n_cells(); }
  double FixedOrificeField::bore_radius() const { return impl->bore_radius; }
  const SimplecSolver &FixedOrificeField::solver() const { return impl->solver; }
  const FvMesh &FixedOrificeField::mesh() const { return impl->mesh; }

  // ---- nozzle-flapper gap ----------------------------------------------------------------------

  struct NozzleFlapperField::Implementation
  {
    double nozzle_diameter, gap;
    FluidProperties fluid;
    FvMesh mesh;
    SimplecSolver solver;
    std::vector<unsigned int> exit_faces; ///< interior faces of the bore's exit section x = 0, r < r_N

    static FvMesh make_mesh(const ValveDescription &valve, const PilotFieldCase &c, double h, double &D_N)
    {
      const auto g = geometry_at(valve, c.temperature);
      D_N = g.nozzle_diameter;
      const double rn = 0.5 * D_N, rl = 0.5 * g.land_diameter;
      if (!(h > 0))
        throw InputError("flow: nozzle-flapper gap " + format_number(h) + " m must be > 0 at the field level");
      const std::map<std::string, double> parameters{
        {"rn", rn / mm},     {"rl", rl / mm},     {"h", h / mm},      {"ro", valve.pilot.field_outlet_radius * rl / mm},
        {"rc", 2 * rn / mm}, {"lc", 2 * rn / mm}, {"lb", 4 * rn / mm}, {"le", 2 * rn / mm},
        {"res", c.resolution}};
      return FvMesh(mesh_template_all_groups({"meshes/nozzle_flapper.geo", embedded::nozzle_flapper_geo, mm}, parameters),
                    Geometry::axisymmetric, "meshes/nozzle_flapper.geo");
    }

    Implementation(const ValveDescription &valve, const PilotFieldCase &c, double h)
      : gap(h)
      , fluid(c.fluid)
      , mesh(make_mesh(valve, c, h, nozzle_diameter))
      , solver(mesh, fluid,
               {{"inlet", BoundaryCondition::total_pressure_inlet(0)},
                {"outlet", BoundaryCondition::pressure_outlet(0)},
                {"nozzle", BoundaryCondition::wall()},
                {"land", BoundaryCondition::wall()},
                {"nozzle_outside", BoundaryCondition::wall()},
                {"flapper", BoundaryCondition::wall()},
                {"axis", BoundaryCondition::axis()}},
               valve.flow_solver)
    {
      const double rn = 0.5 * nozzle_diameter, tolerance = 1e-6 * rn;
      for (std::size_t f = 0; f < mesh.n_faces(); ++f)
        if (mesh.neighbour[f] >= 0 && std::abs(mesh.face_center[f].x()) < tolerance && mesh.face_center[f].y() < rn)
          exit_faces.push_back(f);
    }
  };

  NozzleFlapperField::NozzleFlapperField(const ValveDescription &valve, const PilotFieldCase &c, double gap)
    : impl(std::make_unique<Implementation>(valve, c, gap))
  {}
  NozzleFlapperField::~NozzleFlapperField() = default;

  void NozzleFlapperField::initialize_from(const NozzleFlapperField &other) { impl->solver.initialize_from(other.impl->solver); }

  PilotFieldResult NozzleFlapperField::solve(double dp)
  {
    auto &d = *impl;
    PilotFieldResult r = solve_case(d.solver, dp, "nozzle-flapper");
    const double D_N = d.nozzle_diameter, h = d.gap, v_ideal = ideal_velocity(dp, d.fluid.density);
    r.discharge_coefficient = r.flow_rate / (units::pi * D_N * h * v_ideal); // curtain area (4.2)
    const double hydraulic_diameter = 2 * units::pi * D_N * h / (units::pi * D_N + h);
    r.reynolds_number = hydraulic_diameter * r.discharge_coefficient * v_ideal * d.fluid.density / d.fluid.viscosity; // E18
    const Vector2 axial(1, 0);
    r.flapper_force = d.solver.pressure_force("flapper", axial);
    r.land_force = d.solver.pressure_force("land", -axial);
    double sum = 0, area = 0;
    const auto &p = d.solver.pressure();
    for (unsigned int f : d.exit_faces)
      {
        const double w = d.mesh.face_weight(f);
        sum += (w * p[d.mesh.owner[f]] + (1 - w) * p[d.mesh.neighbour[f]]) * d.mesh.face_area[f];
        area += d.mesh.face_area[f];
      }
    r.bore_pressure = sum / area;
    return r;
  }

  void NozzleFlapperField::set_failure_output(const std::string &f) { impl->solver.failure_output = f; }
  void NozzleFlapperField::write_vtu(const std::string &filename) const { impl->solver.write_vtu(filename); }
  std::size_t NozzleFlapperField::n_cells() const { return impl->mesh.n_cells(); }
  const SimplecSolver &NozzleFlapperField::solver() const { return impl->solver; }
  const FvMesh &NozzleFlapperField::mesh() const { return impl->mesh; }
} // namespace servodrift::flow
