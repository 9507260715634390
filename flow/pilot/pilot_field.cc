#include "flow/pilot/pilot_field.h"
#include "flow/fv/field_transfer.h"
#include "flow/pilot/pilot_field_extraction.h"

#include "common/error.h"
#include "common/gmsh_mesh.h"
#include "common/thermal_laws.h"
#include "common/units.h"
#include "common/valve_description.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>

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
    /// Start-up: a case at rest is first solved laminar at these ideal-velocity Reynolds numbers in
    /// turn (those below its own), then carried to its own. From rest at 30 the flow is nearly a
    /// creeping flow and SIMPLEC converges in about 200 iterations; at 300 from rest it wandered for
    /// 700 iterations before converging (RV-1's null: 1 000 start-up iterations of 1 528), and laminar
    /// runs from rest at Re_0 of about 1000 and above do not settle. The step through 300 keeps the
    /// jump to the case's own pressure level small enough on fine meshes (resolution 1.4 diverged when
    /// carried from 30 straight to Re_0 ~ 2000).
    constexpr double start_up_reynolds_numbers[] = {30, 300};
    /// The start-up rungs are starting states, not answers: converged to scaled residuals of 1e-3
    /// instead of `Tolerance' they save 18 % of a nozzle case's iterations from rest (RV-1's null,
    /// resolution 1 and 2) with C_dn and force unchanged in the fourth digit; 1e-2 moved the laminar
    /// cavitating case's C_dn by 0.1 % (the vapour region remembers the path). The intermediate
    /// levels of a continuation path are starting states too and stop there, without waiting for
    /// the monitored Q and force to settle: 4-23 % fewer iterations than converging them fully, the
    /// answers the same to five digits (RV-1's nozzle: laminar at 60, 110, 120 degC, 20-40 um,
    /// 3.09 MPa, the quasi-static branch each time; k-epsilon at 40 and 110 degC, 3.09-20.6 MPa).
    constexpr double start_up_tolerance = 1e-3;
    /// The liquid check's solve (check_liquid_flow) only decides whether a case cavitates: with 1e-2
    /// instead of the start-up tolerance RV-1's default sweep gave the same tables (to 1e-4) with
    /// 1.3 % more flow-stage time than without the check instead of 3.7 %. Its one possible
    /// error, a liquid flow that is still on its way below the vapour pressure, mends itself:
    /// the case's own solve starts from it with cavitation on and its cells cavitate there.
    constexpr double liquid_check_tolerance = 1e-2;
    /// The liquid check decides `cavitating' before that tolerance once the largest residual is
    /// below liquid_check_decision_residual and the lowest pressure is more than
    /// liquid_check_decision_margin dp below the vapour pressure. RV-1's default sweep (101 checks,
    /// 62 of them cavitating): after the residuals fell below 0.1 the lowest pressure of a check rose
    /// by at most 0.036 dp before its end, and no liquid check's went below +0.012 dp, so a margin of
    /// 0.1 dp is nearly three times the largest rise; 60 of the 62 are decided early, 2 681 of the
    /// checks' 10 959 iterations fewer, the decisions and tables unchanged (doc/method.md).
    constexpr double liquid_check_decision_residual = 1e-1;
    constexpr double liquid_check_decision_margin = 0.1;
    /// Grid sequencing (`Pilot stage/Field mesh/Grid sequencing'): a case at rest on a mesh of this
    /// resolution or finer is first solved on the mesh of half its resolution (a quarter of the
    /// cells, itself sequenced if fine enough), and starts from those fields carried over
    /// (transfer_fields). The start-up ladder's iterations
    /// grow with the mesh (RV-1's null: 538 at resolution 1, 1 278 at 2, most of them at the start-up
    /// rungs), the carried state needs a few hundred. Coarser meshes start up directly: their
    /// half-resolution mesh would be too coarse to resolve the gap's flow.
    constexpr double grid_sequencing_resolution = 1.5;

    /// The pressure levels of a solution path from the level `from' the fields were solved at (0:
    /// none) to `to', the last one: geometric, successive levels at most `ratio' apart.
    std::vector<double> continuation_levels(double from, double to, double ratio)
    {
      if (!(from > 0) || from == to)
        return {to};
      const double steps = std::ceil(std::abs(std::log(to / from)) / std::log(ratio) * (1 - 1e-12));
      std::vector<double> levels;
      for (double k = 1; k < steps; ++k)
        levels.push_back(from * std::pow(to / from, k / steps));
      levels.push_back(to);
      return levels;
    }

    FvMesh make_mesh(const PilotFieldMeshParameters &settings, PilotGeometry kind, const PilotFieldCase &c, double h,
                     double &bore_radius)
    {
      const auto &g = c.dimensions;
      if (kind == PilotGeometry::fixed_orifice)
        {
          const double r0 = 0.5 * g.fixed_orifice_diameter, plenum = settings.plenum_size * r0;
          bore_radius = r0;
          const std::map<std::string, double> parameters{
            {"r0", r0 / mm},           {"l", g.fixed_orifice_length / mm}, {"ru", plenum / mm},
            {"lu", plenum / mm},       {"rd", 8 * r0 / mm},                {"ld", settings.chamber_length * r0 / mm},
            {"res", c.resolution}};
          return FvMesh(mesh_template_all_groups({"meshes/fixed_orifice.geo", embedded::fixed_orifice_geo, mm, "Pilot stage"}, parameters),
                        Geometry::axisymmetric, "meshes/fixed_orifice.geo");
        }
      const double rn = 0.5 * g.nozzle_diameter, rl = 0.5 * g.land_diameter;
      bore_radius = rn;
      if (!(h > 0) || !std::isfinite(h))
        throw InputError("flow: nozzle-flapper gap " + format_number(h) + " m must be > 0 at the field level");
      const std::map<std::string, double> parameters{
        {"rn", rn / mm},     {"rl", rl / mm},     {"h", h / mm},       {"ro", settings.outlet_radius * rl / mm},
        {"rc", 2 * rn / mm}, {"lc", 2 * rn / mm}, {"lb", nozzle_bore_length_in_radii * rn / mm}, {"le", 2 * rn / mm},
        {"res", c.resolution}};
      return FvMesh(mesh_template_all_groups({"meshes/nozzle_flapper.geo", embedded::nozzle_flapper_geo, mm, "Pilot stage"}, parameters),
                    Geometry::axisymmetric, "meshes/nozzle_flapper.geo");
    }

    std::map<std::string, BoundaryCondition> boundaries(PilotGeometry kind)
    {
      std::map<std::string, BoundaryCondition> b{{"inlet", BoundaryCondition::total_pressure_inlet(0)},
                                                 {"outlet", BoundaryCondition::pressure_outlet(0)},
                                                 {"axis", BoundaryCondition::axis()}};
      if (kind == PilotGeometry::fixed_orifice)
        b.emplace("wall", BoundaryCondition::wall());
      else
        for (const char *wall : {"nozzle", "land", "nozzle_outside", "flapper"})
          b.emplace(wall, BoundaryCondition::wall());
      return b;
    }

    /// The valve's flow solver settings for a case of this geometry with flow model t (the nozzle's
    /// own stall window, `Pilot stage/Field solution/Nozzle stall window').
    FlowSolverParameters solver_settings(const PilotFieldSettings &settings, PilotGeometry kind,
                                         FlowSolverParameters::Turbulence t)
    {
      FlowSolverParameters s = settings.solver;
      s.turbulence = t;
      if (kind == PilotGeometry::nozzle_flapper)
        s.stall_window = settings.solution.nozzle_stall_window;
      return s;
    }
  } // namespace

  PilotFieldSettings pilot_field_settings(const ValveDescription &valve)
  {
    const auto &operating = valve.operating;
    return {valve.pilot.field_mesh,        valve.pilot.field_solution,    valve.flow_solver,
            operating.supply_pressure,     operating.return_pressure,     operating.ambient_pressure,
            valve.fluid.vapour_pressure};
  }

  PilotFieldCase pilot_field_case(const ValveDescription &valve, double T)
  {
    const double T0 = valve.operating.reference_temperature;
    const laws::Oil oil(valve.fluid, T0);
    oil.check_temperature(T, "flow case temperature");
    return {T, {oil.density(T).value, oil.dynamic_viscosity(T)}, valve.pilot.field_mesh.resolution, valve.flow_solver.turbulence,
            laws::pilot_stage_geometry(valve.pilot, valve.armature, valve.expansion, T, T0)};
  }

  struct PilotField::Implementation
  {
    PilotGeometry kind;
    PilotFieldSettings settings;
    PilotFieldCase conditions;
    double gap, bore_radius = 0;
    FvMesh mesh;
    SimplecSolver solver;
    bool at_rest = true;
    bool fields_from_elsewhere = false; ///< set_fields() since the last solve, of another gap or temperature
    /// the pressure level the solver's settings were last prepared for (prepare_level); 0 after
    /// set_fields(), whose fields bring their inlet pressure but not the cavitation model's state
    double prepared_level = 0;
    double continuation_ratio; ///< largest ratio of successive pressure levels (`Field solution/Continuation ratio')
    std::vector<unsigned int> exit_faces; ///< nozzle: interior faces of the bore's exit section x = 0, r < r_N

    Implementation(const PilotFieldSettings &settings_, PilotGeometry kind_, const PilotFieldCase &c, double h)
      : kind(kind_)
      , settings(settings_)
      , conditions(c)
      , gap(h)
      , mesh(make_mesh(settings_.mesh, kind_, c, h, bore_radius))
      , solver(mesh, c.fluid, boundaries(kind_), solver_settings(settings_, kind_, c.turbulence))
      , continuation_ratio(settings_.solution.continuation_ratio)
    {
      if (kind == PilotGeometry::nozzle_flapper)
        {
          const double tolerance = 1e-6 * bore_radius;
          for (std::size_t f = 0; f < mesh.n_faces(); ++f)
            if (mesh.neighbour[f] >= 0 && std::abs(mesh.face_center[f].x()) < tolerance &&
                mesh.face_center[f].y() < bore_radius)
              exit_faces.push_back(f);
        }
      // converged when, besides the residuals, Q (and the flapper force) settle (issue 5)
      const auto &s = settings.solver;
      solver.set_convergence_monitor(
        [this] {
          std::vector<double> m{solver.flow_rate("outlet")};
          if (kind == PilotGeometry::nozzle_flapper)
            m.push_back(solver.pressure_force("flapper", Vector2(1, 0)));
          return m;
        },
        s.monitor_iterations, s.monitor_tolerance);
    }

    double ideal_reynolds_number(double dp) const
    {
      const double length = kind == PilotGeometry::fixed_orifice ? 2 * bore_radius : 2 * gap;
      return length * ideal_velocity(dp, conditions.fluid.density) * conditions.fluid.density / conditions.fluid.viscosity;
    }

    /// The outlet's absolute pressure at pressure difference dp: the control pressure p_s - dp
    /// downstream of the orifice, the return pressure downstream of the nozzle (gauge + ambient).
    double downstream_pressure(double dp) const
    {
      return (kind == PilotGeometry::fixed_orifice ? settings.supply_pressure - dp : settings.return_pressure) +
             settings.ambient_pressure;
    }

    /// One step of the solution path: the fields scaled to the pressure level dp (from the inlet
    /// pressure they were solved at), the vapour pressure at that level's outlet pressure, solved
    /// (an intermediate level only to `intermediate_tolerance' if that is > 0).
    SolveReport solve_at(double dp, double intermediate_tolerance = 0)
    {
      prepare_level(solver, dp, settings.solution.cavitation);
      return intermediate_tolerance > 0 ? solver.solve_to(std::max(intermediate_tolerance, settings.solver.tolerance), false) :
                                          solver.solve();
    }

    /// The fields of `s' scaled to the pressure level dp (from the inlet pressure they were solved
    /// at), the inlet's pressure, the turbulent viscosity's limit and, with `cavitation', the vapour
    /// pressure at that level.
    void prepare_level(SimplecSolver &s, double dp, bool cavitation)
    {
      const double previous = s.boundary_pressure("inlet");
      if (previous > 0 && previous != dp)
        s.scale_pressure_level(dp / previous);
      s.set_boundary_pressure("inlet", dp);
      if (&s == &solver)
        prepared_level = dp;
      s.set_turbulent_viscosity_limit(settings.solution.turbulent_viscosity_limit * ideal_reynolds_number(dp));
      at_rest = false;
      if (cavitation)
        s.set_cavitation_pressure(settings.vapour_pressure - downstream_pressure(dp));
    }

    /// What the current fields give at pressure difference dp (model.md 4.2): Q, C_d, Re, the
    /// forces and the diagnostics, Q through the patch `metered'; the iteration counts are the
    /// caller's.
    PilotFieldResult result_of(double dp, MeteredAt metered) const;

    /// A case at rest on a fine mesh: the case solved on the mesh of half the resolution, carried
    /// over. Returns false (and leaves the fields at rest) if that solve fails; the caller then
    /// starts up on this mesh.
    bool start_from_coarser_mesh(double dp, unsigned int &coarse_iterations)
    {
      PilotFieldCase coarse_case = conditions;
      coarse_case.resolution = 0.5 * conditions.resolution;
      try
        {
          PilotField coarse(settings, kind, coarse_case, gap);
          const PilotFieldResult r = coarse.solve(dp);
          coarse_iterations += r.iterations + r.coarse_mesh_iterations;
          solver.set_fields(transfer_fields(coarse.impl->mesh, coarse.impl->solver.fields(), mesh));
          return true;
        }
      catch (const InputError &)
        {
          throw; // the case itself is wrong: the same error on this mesh
        }
      catch (const std::exception &)
        {
          return false;
        }
    }

    /// Whether a case that starts from other fields cavitates at dp: its liquid flow, from those
    /// fields without their cavity, solved to liquid_check_tolerance by a solver of its own. If its
    /// lowest pressure stays at or above the vapour pressure, the case goes on from that flow and
    /// cells cavitate only where its own solve falls below (inception); otherwise (or if that solve
    /// fails) it goes on from the fields it was given, cavity and all, on the quasi-static path, as
    /// if there had been no check. Why: a cavity carried over, or made by the iteration's excursions
    /// below the vapour pressure on the way from another case's fields, can stay where the case's
    /// liquid flow is far above the vapour pressure, a steady state of the equilibrium model that is
    /// not the flow's. RV-1's default sweep carried such cavities (1-30 cells) in ten 10 um cases at
    /// 3.09 and 10.3 MPa whose liquid flow stays 0.14-0.48 MPa above it; they moved C_d by -2.2 to
    /// +4.7 % and the force by up to 4.3 %, and marched in time (with the cavitation model) they
    /// collapse within 1-4.4 us (bench_narrow_gap_paths). Returns the iterations.
    unsigned int check_liquid_flow(double dp)
    {
      FlowFields start = solver.fields();
      start.liquid_fraction.clear(), start.cavitating.clear(); // set_fields: every cell liquid
      SimplecSolver liquid(mesh, conditions.fluid, boundaries(kind), solver_settings(settings, kind, conditions.turbulence));
      liquid.set_fields(start);
      const double tolerance = std::max(liquid_check_tolerance, settings.solver.tolerance);
      const auto lowest_absolute_pressure = [&] { return downstream_pressure(dp) + liquid.minimum_pressure(); };
      // an answer that is already clear: the liquid flow far below the vapour pressure (at its own level)
      const std::function<bool(const Residuals &)> clearly_cavitating = [&](const Residuals &r) {
        return largest_residual(r) < liquid_check_decision_residual &&
               lowest_absolute_pressure() < settings.vapour_pressure - liquid_check_decision_margin * dp;
      };
      unsigned int iterations = 0;
      try
        {
          for (const double level : continuation_levels(liquid.boundary_pressure("inlet"), dp, continuation_ratio))
            {
              prepare_level(liquid, level, false);
              const auto decided = level == dp ? clearly_cavitating : std::function<bool(const Residuals &)>();
              iterations += liquid.solve_to(tolerance, false, decided).iterations;
            }
          if (lowest_absolute_pressure() >= settings.vapour_pressure)
            solver.set_fields(liquid.fields());
        }
      catch (const std::runtime_error &)
        {
        }
      return iterations;
    }

    /// The current fields hold a cavity.
    bool carries_cavity() const
    {
      const std::vector<double> gamma = solver.liquid_fraction();
      return std::any_of(gamma.begin(), gamma.end(), [](double g) { return g < 1; });
    }

    /// A case at rest: laminar solves at the start-up Reynolds numbers on the same mesh, whose
    /// fields this case then continues from. Returns their iterations.
    unsigned int start_up(double dp)
    {
      const double Re = ideal_reynolds_number(dp);
      FlowSolverParameters s = solver_settings(settings, kind, FlowSolverParameters::Turbulence::laminar);
      s.tolerance = std::max(s.tolerance, start_up_tolerance);
      SimplecSolver laminar(mesh, conditions.fluid, boundaries(kind), s);
      laminar.failure_output = solver.failure_output;
      unsigned int iterations = 0;
      double level = 0;
      for (const double start_Re : start_up_reynolds_numbers)
        {
          const double dp_start = dp * std::pow(std::min(start_Re / Re, 1.0), 2);
          if (level > 0)
            {
              if (dp_start <= level)
                break;
              laminar.scale_pressure_level(dp_start / level);
            }
          laminar.set_boundary_pressure("inlet", dp_start);
          iterations += laminar.solve().iterations;
          level = dp_start;
        }
      solver.set_fields(laminar.fields());
      at_rest = false;
      return iterations;
    }
  };

  PilotField::PilotField(const PilotFieldSettings &settings, PilotGeometry geometry, const PilotFieldCase &c, double gap)
    : impl(std::make_unique<Implementation>(settings, geometry, c, gap))
  {}
  PilotField::~PilotField() = default;
  PilotField::PilotField(PilotField &&) noexcept = default;

  PilotFieldResult PilotField::solve(double dp)
  {
    auto &d = *impl;
    const char *what = d.kind == PilotGeometry::fixed_orifice ? "fixed orifice" : "nozzle-flapper";
    if (!(dp > 0) || !std::isfinite(dp))
      throw InputError(std::string("flow: ") + what + ": pressure difference " + format_number(dp) +
                       " Pa must be > 0 (inlet total pressure above the outlet's)");
    PilotFieldResult r;
    // whether the case cavitates is open where it starts from another gap's or temperature's
    // fields, from liquid fields or from a higher pressure level; a cavity of its own at a lower
    // level stays (it only grows with the pressure difference: the quasi-static path), whether
    // carried on or given back by the chain's retries or model switches
    const bool cavity_from_below = d.carries_cavity() && d.solver.boundary_pressure("inlet") <= dp;
    if (!d.at_rest && d.settings.solution.cavitation && (d.fields_from_elsewhere || !cavity_from_below))
      r.iterations += d.check_liquid_flow(dp);
    d.fields_from_elsewhere = false;
    if (d.at_rest && !(d.settings.mesh.grid_sequencing && d.conditions.resolution >= grid_sequencing_resolution &&
                       d.start_from_coarser_mesh(dp, r.coarse_mesh_iterations)))
      r.iterations += d.start_up(dp);
    // continuation from the last fields to dp, through geometric intermediate levels no more than
    // the continuation ratio apart (the quasi-static path; `Field solution/Continuation ratio')
    SolveReport report;
    for (const double level : continuation_levels(d.solver.boundary_pressure("inlet"), dp, d.continuation_ratio))
      {
        report = d.solve_at(level, level == dp ? 0.0 : start_up_tolerance);
        r.iterations += report.iterations;
      }
    r.pressure_relaxation = report.pressure_relaxation;
    if (report.cells_at_viscosity_limit > 0)
      throw NotConverged(std::string("flow: ") + what + ": converged with the turbulent viscosity held at its limit (" +
                         format_number(d.settings.solution.turbulent_viscosity_limit) + " Re mu) in " +
                         std::to_string(report.cells_at_viscosity_limit) +
                         " cells: not the model's solution; raise `Pilot stage/Field solution/Turbulent viscosity limit'",
                         report.residuals);
    const PilotFieldResult fields = d.result_of(dp, MeteredAt::outlet);
    const unsigned int iterations = r.iterations, coarse = r.coarse_mesh_iterations;
    const double relaxation = r.pressure_relaxation;
    r = fields;
    r.iterations = iterations, r.coarse_mesh_iterations = coarse, r.pressure_relaxation = relaxation;
    r.residuals = report.residuals;
    return r;
  }

  PilotFieldResult PilotField::Implementation::result_of(double dp, MeteredAt metered) const
  {
    return extract_pilot_result(solver, mesh, {kind, gap, bore_radius, exit_faces}, conditions,
                                settings.vapour_pressure, downstream_pressure(dp), dp, metered);
  }

  PilotFieldResult PilotField::advance(double dp, double dt, unsigned int max_iterations, double tolerance)
  {
    auto &d = *impl;
    // after set_fields() too: the given fields carry their pressure level, but a march without
    // prepare_level would run without the cavitation model
    if (d.prepared_level != dp || d.solver.boundary_pressure("inlet") != dp)
      d.prepare_level(d.solver, dp, d.settings.solution.cavitation);
    const SolveReport step = d.solver.advance(dt, max_iterations, tolerance);
    PilotFieldResult r = d.result_of(dp, MeteredAt::inlet);
    r.iterations = step.iterations;
    r.pressure_relaxation = step.pressure_relaxation;
    r.step_converged = step.converged;
    r.residuals = step.residuals;
    return r;
  }

  double PilotField::courant_time_step(double courant) const { return impl->solver.courant_time_step(courant); }

  void PilotField::initialize_from(const PilotField &other) { set_fields(other.fields()); }
  FlowFields PilotField::fields() const { return impl->solver.fields(); }
  void PilotField::set_fields(const FlowFields &f)
  {
    impl->solver.set_fields(f);
    impl->at_rest = false;
    impl->prepared_level = 0;
    impl->fields_from_elsewhere = f.density != impl->conditions.fluid.density || f.face_area != impl->mesh.face_area;
  }
  bool PilotField::at_rest() const { return impl->at_rest; }
  void PilotField::set_continuation_ratio(double ratio)
  {
    if (!(ratio > 1) || !std::isfinite(ratio))
      throw std::invalid_argument("flow: continuation ratio " + format_number(ratio) + " must be > 1");
    impl->continuation_ratio = ratio;
  }
  void PilotField::set_failure_output(const std::string &f) { impl->solver.failure_output = f; }
  void PilotField::write_vtu(const std::string &filename) const { impl->solver.write_vtu(filename); }
  std::size_t PilotField::n_cells() const { return impl->mesh.n_cells(); }
  PilotGeometry PilotField::geometry() const { return impl->kind; }
  double PilotField::gap() const { return impl->gap; }
  double PilotField::bore_radius() const { return impl->bore_radius; }
  double PilotField::ideal_reynolds_number(double dp) const { return impl->ideal_reynolds_number(dp); }
  const SimplecSolver &PilotField::solver() const { return impl->solver; }
  SimplecSolver &PilotField::solver() { return impl->solver; }
  const FvMesh &PilotField::mesh() const { return impl->mesh; }
} // namespace servodrift::flow
