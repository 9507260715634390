// The checks of a valve description that go beyond one entry's range (declared in
// valve_description.h): every condition that can be checked from the description alone, before
// any stage runs or writes (issue 24).
#include "common/error.h"
#include "common/thermal_laws.h"
#include "common/units.h"
#include "common/valve_description.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace servodrift
{
  namespace
  {
    [[noreturn]] void refuse(const std::string &entry, const std::string &what)
    {
      throw InputError("`" + entry + "' " + what);
    }

    void require_increasing(const std::vector<double> &list, const std::string &entry, double scale = 1.0)
    {
      for (std::size_t k = 1; k < list.size(); ++k)
        if (!(list[k] > list[k - 1]))
          refuse(entry, "must be strictly increasing, but " + format_number(list[k - 1] / scale) +
                          " is followed by " + format_number(list[k] / scale));
    }
  } // namespace

  void validate_dynamics(const ValveDescription &v)
  {
    const auto &d = v.dynamics;
    const auto &op = v.operating;
    const auto &sw = v.sweeps;
    if (!(d.minimum_frequency < d.maximum_frequency))
      refuse("Dynamics/Minimum frequency", "= " + format_number(d.minimum_frequency) +
                                             " Hz must be below `Dynamics/Maximum frequency' = " +
                                             format_number(d.maximum_frequency) + " Hz");
    require_increasing(d.sine_frequencies, "Dynamics/Sine frequencies");
    require_increasing(d.sine_amplitudes, "Dynamics/Sine amplitudes");
    require_increasing(d.reading_times, "Dynamics/Reading times");
    require_increasing(d.cold_start_temperatures, "Dynamics/Cold-start temperatures");
    const auto &tm = v.torque_motor;
    if (tm.voltage_drive && !(tm.coil_resistance > 0 && tm.coil_inductance > 0))
      refuse("Torque motor/Coil inductance", "and `Torque motor/Coil resistance' must be > 0 under voltage drive "
                                             "(`Torque motor/Coil drive' = voltage)");

    // Every current the analyses command must lie in the torque table: bias -+ the largest sine
    // amplitude, the small step, 0 and the rated current. Under voltage drive the coil current is a
    // state: a cold coil draws R_c(T0)/R_c(T) of the command, and near the armature's resonance the
    // back-EMF lets it overshoot by some 10 %, so the table must reach 1.25 times that.
    double ratio = 1;
    if (tm.voltage_drive)
      {
        for (double T : sw.drift_temperatures)
          ratio = std::max(ratio, laws::coil_resistance(tm, op.reference_temperature) / laws::coil_resistance(tm, T));
        ratio *= 1.25;
      }
    const double rated = op.rated_current, bias = d.bias * rated;
    const double amplitude = std::max(d.sine_amplitudes.back(), d.sine_check_amplitude) * rated;
    const double lowest = std::min({0.0, bias - amplitude}) * ratio;
    const double highest =
      std::max({rated, bias + amplitude, bias + d.small_step * rated, d.cold_start_current * rated}) * ratio;
    const auto &currents = sw.motor_currents;
    if (lowest < currents.front() || highest > currents.back())
      refuse("Dynamics/Sine amplitudes",
             "with `Dynamics/Bias' = " + format_number(d.bias) + " command currents from " + format_number(lowest) +
               " to " + format_number(highest) + " A" +
               (tm.voltage_drive ? " (under voltage drive: a cold coil's current with 25 % for its overshoot)" : "") +
               ", beyond the torque table's `Sweeps/Motor currents' [" + format_number(currents.front()) + ", " +
               format_number(currents.back()) + "] A; lower the amplitudes or the bias, or extend the currents");
    // The flapper may reach a nozzle in a transient (it saturates there): the torque table must
    // reach the nozzle contacts, theta = (+-x0(T) + x_n)/r.
    double contact = 0;
    for (double T : sw.table_temperatures)
      {
        const auto g = laws::pilot_stage_geometry(v.pilot, v.armature, v.expansion, T, op.reference_temperature);
        contact = std::max(contact, (g.null_gap + std::abs(v.offsets.hydraulic_null)) / v.armature.pivot_to_nozzle_distance +
                                      std::abs(v.offsets.magnetic_null));
      }
    if (-sw.motor_angles.front() < contact || sw.motor_angles.back() < contact)
      refuse("Sweeps/Motor angles",
             "must reach the nozzle contacts at +-" + format_number(1.001 * contact / units::degree) +
               " deg for the dynamics, where the flapper may hit a nozzle in a transient" +
               (v.offsets.magnetic_null != 0 || v.offsets.hydraulic_null != 0 ?
                  " (they include `Offsets/Magnetic null' = " + format_number(v.offsets.magnetic_null / units::degree) +
                    " deg and `Offsets/Hydraulic null' = " + format_number(v.offsets.hydraulic_null) + " m)" :
                  std::string()) +
               " (or set `Dynamics/Enabled' = false)");
  }

  void validate_table_ranges(const ValveDescription &v)
  {
    // the bridge's control pressure may lie anywhere between return and supply: every pressure
    // list of the pilot tables must reach the whole span p_s - p_r (the reduced-order one from 0)
    const auto &sw = v.sweeps;
    std::vector<std::pair<const std::vector<double> *, const char *>> lists;
    if (v.pilot.model_level == "field")
      lists = {{&sw.field_orifice_pressure_fractions, "Sweeps/Field orifice pressure fractions"},
               {&sw.field_nozzle_pressure_fractions, "Sweeps/Field nozzle pressure fractions"}};
    else
      {
        lists = {{&sw.pressure_fractions, "Sweeps/Pressure fractions"}};
        if (!(sw.pressure_fractions.front() == 0))
          refuse("Sweeps/Pressure fractions", "starts with " + format_number(sw.pressure_fractions.front()) +
                                                "; it must start with 0, the laminar limit of the pilot flows");
      }
    for (const auto &[list, entry] : lists)
      if (!(list->back() == 1))
        refuse(entry, "ends with " + format_number(list->back()) +
                        "; it must end with 1 (p_s - p_r) for `servodrift run': the pilot bridge's control "
                        "pressure may lie anywhere between return and supply");
    if (!v.pilot.model_form_alternatives.empty() && v.pilot.model_level != "field")
      refuse("Pilot stage/Model-form alternatives",
             "lists other flow models, which only the field level has; set `Pilot stage/Model level' = field or "
             "leave it empty");
  }

  void validate(const ValveDescription &v)
  {
    const auto &op = v.operating;
    if (!(v.pilot.field_time_steps_limit >= v.pilot.field_time_steps))
      refuse("Pilot stage/Field time steps limit", "= " + std::to_string(v.pilot.field_time_steps_limit) +
                                                     " must be at least `Pilot stage/Field time steps' = " +
                                                     std::to_string(v.pilot.field_time_steps));
    if (!(op.rated_current > 0))
      refuse("Operating conditions/Rated current", "= " + format_number(op.rated_current) +
                                                     " A must be > 0: drifts are given in % of it (D7, D9)");
    if (!(op.return_pressure < op.supply_pressure))
      refuse("Operating conditions/Return pressure",
             "= " + format_number(op.return_pressure) + " Pa must be below the supply pressure " +
               format_number(op.supply_pressure) + " Pa");

    // Sweep lists
    const auto &sw = v.sweeps;
    require_increasing(sw.table_temperatures, "Sweeps/Table temperatures");
    require_increasing(sw.motor_angles, "Sweeps/Motor angles", units::degree);
    require_increasing(sw.motor_currents, "Sweeps/Motor currents");
    require_increasing(sw.pressure_fractions, "Sweeps/Pressure fractions");
    require_increasing(sw.gap_fractions, "Sweeps/Gap fractions");
    require_increasing(sw.field_orifice_pressure_fractions, "Sweeps/Field orifice pressure fractions");
    require_increasing(sw.field_gap_fractions, "Sweeps/Field gap fractions");
    require_increasing(sw.field_nozzle_pressure_fractions, "Sweeps/Field nozzle pressure fractions");
    for (const auto &[list, entry] : {std::make_pair(&sw.field_orifice_pressure_fractions, "Sweeps/Field orifice pressure fractions"),
                                      std::make_pair(&sw.field_gap_fractions, "Sweeps/Field gap fractions"),
                                      std::make_pair(&sw.field_nozzle_pressure_fractions, "Sweeps/Field nozzle pressure fractions")})
      if (!(list->front() > 0))
        refuse(entry, "starts with " + format_number(list->front()) +
                        ": the field level computes only flowing cases (> 0; the table adds the zero row itself)");
    require_increasing(sw.drift_temperatures, "Sweeps/Drift temperatures");
    require_increasing(sw.deviation_angles, "Sweeps/Deviation angles", units::degree);

    // Temperatures inside the oil law's window (E16 is singular at T = -C)
    const auto &fl = v.fluid;
    if (!(fl.minimum_temperature < fl.maximum_temperature))
      refuse("Fluid/Minimum temperature", "= " + format_number(fl.minimum_temperature) +
                                            " degC must be below `Fluid/Maximum temperature' = " +
                                            format_number(fl.maximum_temperature) + " degC");
    if (fl.viscosity_law == FluidParameters::ViscosityLaw::vogel && !(fl.minimum_temperature > -fl.vogel_c))
      refuse("Fluid/Minimum temperature", "= " + format_number(fl.minimum_temperature) +
                                            " degC must be above -`Fluid/Vogel C' = " +
                                            format_number(-fl.vogel_c) + " degC, where E16 is singular");
    auto check_window = [&](const std::vector<double> &list, const std::string &entry) {
      for (double T : list)
        if (!(T >= fl.minimum_temperature && T <= fl.maximum_temperature))
          refuse(entry, "contains " + format_number(T) + " degC, outside the oil viscosity law's window [" +
                          format_number(fl.minimum_temperature) + ", " + format_number(fl.maximum_temperature) +
                          "] degC (`Fluid/Minimum temperature', `Fluid/Maximum temperature')");
    };
    check_window(sw.table_temperatures, "Sweeps/Table temperatures");
    check_window(sw.drift_temperatures, "Sweeps/Drift temperatures");
    check_window({op.reference_temperature}, "Operating conditions/Reference temperature");
    // The oil law gives a positive, finite viscosity and density wherever a table is made (E14-E16)
    {
      const laws::Oil oil(fl, op.reference_temperature);
      for (double T : sw.table_temperatures)
        {
          const double nu = oil.kinematic_viscosity(T).value, rho = oil.density(T).value;
          if (!(nu > 0 && std::isfinite(nu) && nu < 1))
            refuse(fl.viscosity_law == FluidParameters::ViscosityLaw::vogel ? "Fluid/Vogel A" : "Fluid/Reference viscosity",
                   "and the other constants of the viscosity law give nu = " + format_number(nu) + " m^2/s at " +
                     format_number(T) + " degC; it must lie in (0, 1) m^2/s at every table temperature (E14, E16)");
          if (!(rho > 0 && std::isfinite(rho)))
            refuse("Fluid/Density temperature coefficient",
                   "= " + format_number(fl.density_temperature_coefficient) + " 1/degC gives a density of " +
                     format_number(rho) + " kg/m^3 at " + format_number(T) + " degC; it must stay > 0 (E15)");
        }
    }
    const double T_lo = sw.table_temperatures.front(), T_hi = sw.table_temperatures.back();
    auto check_in_tables = [&](double T, const std::string &entry) {
      if (!(T >= T_lo && T <= T_hi))
        refuse(entry, "contains " + format_number(T) + " degC, outside the table temperatures [" +
                        format_number(T_lo) + ", " + format_number(T_hi) + "] degC (`Sweeps/Table temperatures')");
    };
    for (double T : sw.drift_temperatures)
      check_in_tables(T, "Sweeps/Drift temperatures");
    check_in_tables(op.reference_temperature, "Operating conditions/Reference temperature");

    // Torque motor: gaps open at every temperature and every tabulated angle (E2, E6, E7)
    const auto &tm = v.torque_motor;
    if (!(tm.pivot_to_pole_distance > 0 && tm.pole_face_width > 0 && tm.pole_face_length > 0 &&
          tm.magnet_length > 0 && tm.magnet_width > 0 && tm.magnet_depth > 0))
      refuse("Torque motor", "dimensions (pivot distance, pole face, magnet) must all be > 0");
    // The magnets polarise the motor: without remanence, or with the leakage path shorting them,
    // no flux crosses the working gaps, K_m = 0 and the magnetic null is undefined (E3, E8)
    if (!(tm.remanence * (1 - tm.irreversible_loss) > 0))
      refuse("Torque motor/Remanence", "= " + format_number(tm.remanence) + " T with `Torque motor/Irreversible loss' = " +
                                         format_number(tm.irreversible_loss) +
                                         " leaves the magnets without remanence: no polarising flux, no torque "
                                         "(E8); B_r0 (1 - R_irr) must be > 0");
    if (!(tm.leakage_reluctance > 0))
      refuse("Torque motor/Leakage reluctance", "= 0 shorts the magnets: no flux crosses the working gaps, no torque "
                                                "(E3); it must be > 0");
    double max_angle = 0;
    for (double a : sw.motor_angles)
      max_angle = std::max(max_angle, std::abs(a));
    for (double T : sw.table_temperatures)
      {
        const auto g = laws::torque_motor_geometry(tm, v.expansion, T, op.reference_temperature);
        if (!(g.lower_gap > 0))
          refuse("Torque motor/Armature height",
                 "gives a closed lower gap g_12 = H_a - H_ar/2 - H_c = " + format_number(g.lower_gap) + " m at " +
                   format_number(T) + " degC (E6); it must be > 0");
        if (!(g.upper_gap > 0))
          refuse("Torque motor/Armature height",
                 "gives a closed upper gap g_34 = H_c' + H_m - h_p - H_a - H_ar/2 = " + format_number(g.upper_gap) +
                   " m at " + format_number(T) + " degC (E7); it must be > 0");
        // the armature's tip, at the outer edge of the pole faces (or its own end), must not touch
        const double tip = std::max(g.pivot_to_pole_distance + 0.5 * g.pole_face_length,
                                    laws::expanded(tm.armature_length / 2, v.expansion.armature, T, op.reference_temperature));
        const double closing = tip * max_angle;
        const double gap = std::min(g.lower_gap, g.upper_gap);
        if (!(closing < 0.95 * gap))
          refuse("Sweeps/Motor angles",
                 "reach " + format_number(max_angle / units::degree) + " deg, where the armature tip moves " +
                   format_number(closing) + " m of a " + format_number(gap) + " m gap at " + format_number(T) +
                   " degC; keep |angle| below " + format_number(0.95 * gap / tip / units::degree) +
                   " deg, or widen the gap (E6, E7: `Torque motor/Armature height' and the pole and magnet heights)");
      }
    if (!(sw.motor_angles.front() <= -0.1 * units::degree && sw.motor_angles.back() >= 0.1 * units::degree))
      refuse("Sweeps/Motor angles", "must cover -0.1..0.1 deg, where the secant K_m is evaluated (C1)");
    const double i_rated = op.rated_current;
    if (!(sw.motor_currents.front() <= -i_rated && sw.motor_currents.back() >= i_rated))
      refuse("Sweeps/Motor currents", "must cover -rated..rated current, +-" + format_number(i_rated) + " A");

    // Field model of the torque motor (meshes/torque_motor.geo): parts must not overlap
    if (tm.model_level == "field")
      {
        const std::string field = " (field model, meshes/torque_motor.geo)";
        const double pole_tip_start = tm.pivot_to_pole_distance - 0.5 * tm.pole_face_length;
        if (!(tm.coil_height > 0))
          refuse("Torque motor/Coil height", "= " + format_number(tm.coil_height) + " m must be > 0: the coil's current "
                                             "density region needs an area" + field);
        if (!(tm.coil_clearance > 0))
          refuse("Torque motor/Coil clearance", "must be > 0: the coil may not touch the moving armature" + field);
        if (!(tm.coil_inner_position < tm.coil_outer_position))
          refuse("Torque motor/Coil inner position", "= " + format_number(tm.coil_inner_position) +
                                                       " m must be below `Torque motor/Coil outer position' = " +
                                                       format_number(tm.coil_outer_position) + " m" + field);
        if (!(tm.coil_outer_position < pole_tip_start))
          refuse("Torque motor/Coil outer position", "= " + format_number(tm.coil_outer_position) +
                                                       " m reaches the pole tips, which start at " +
                                                       format_number(pole_tip_start) + " m" + field);
        const double upper_plate = tm.upper_pole_thickness + tm.magnet_length - tm.armature_height;
        const double lower_plate = tm.upper_pole_thickness - tm.armature_height;
        const double coil_reach = 0.5 * tm.armature_thickness + tm.coil_clearance + tm.coil_height;
        if (!(coil_reach < upper_plate && -coil_reach > lower_plate))
          refuse("Torque motor/Coil height", "= " + format_number(tm.coil_height) +
                                               " m makes a coil region reach a pole plate" + field);
        if (!(tm.field_magnet_clearance > 0.5 * tm.armature_length - tm.pivot_to_pole_distance - 0.5 * tm.pole_face_length))
          refuse("Torque motor/Field magnet clearance", "puts the magnet blocks over the armature's tip" + field);
        if (!(tm.field_magnet_width > 0))
          refuse("Torque motor/Field magnet width", "must be > 0" + field);
        const double half_size = std::max(tm.pivot_to_pole_distance + 0.5 * tm.pole_face_length + tm.field_magnet_clearance +
                                            tm.field_magnet_width,
                                          tm.armature_height + tm.upper_plate_thickness);
        if (!(tm.air_boundary_radius > 1.5 * half_size))
          refuse("Torque motor/Air boundary radius", "= " + format_number(tm.air_boundary_radius) +
                                                       " m must enclose the motor with room, at least " +
                                                       format_number(1.5 * half_size) + " m" + field);
      }

    // Spring tube
    const auto &st = v.spring_tube;
    if (!(st.outer_diameter > 0 && st.length > 0))
      refuse("Spring tube/Outer diameter", "and `Spring tube/Length' must be > 0");
    if (!(st.inner_diameter < st.outer_diameter))
      refuse("Spring tube/Inner diameter", "= " + format_number(st.inner_diameter) +
                                             " m must be below the outer diameter " +
                                             format_number(st.outer_diameter) + " m (wall thickness > 0)");
    if (st.model_level == "field")
      {
        const std::string field = " for the field level (`Spring tube/Model level = field')";
        if (!(st.inner_diameter > 0))
          refuse("Spring tube/Inner diameter", "= " + format_number(st.inner_diameter) +
                                                 " m must be > 0" + field +
                                                 ": the n = 1 axisymmetric model needs a bore");
        if (!(st.poisson_ratio < 0.5))
          refuse("Spring tube/Poisson ratio", "= " + format_number(st.poisson_ratio) + " must be below 0.5" + field +
                                                " (Lame's lambda is infinite for an incompressible solid)");
        // a flange or collar of height > 0 must stand out of the tube, or there is nothing to mesh
        for (const auto &[part, diameter, height] :
             {std::tuple{"Base flange", st.base_flange_diameter, st.base_flange_height},
              std::tuple{"Top collar", st.top_collar_diameter, st.top_collar_height}})
          if (height > 0 && !(diameter > st.outer_diameter))
            refuse(std::string("Spring tube/") + part + " diameter",
                   "= " + format_number(diameter) + " m must exceed the outer diameter " +
                     format_number(st.outer_diameter) + " m when its height is > 0" + field +
                     " (set the height to 0 for none)");
        const double radial_size = 0.5 * (st.outer_diameter - st.inner_diameter) /
                                   (st.field_wall_layers * st.field_mesh_resolution);
        for (const auto &[entry, height] : {std::pair{"Base flange height", st.base_flange_height},
                                            std::pair{"Top collar height", st.top_collar_height}})
          if (height > 0 && !(height > 0.05 * radial_size))
            refuse(std::string("Spring tube/") + entry,
                   "= " + format_number(height) + " m cannot be meshed: a height above 0 must be at least " +
                     format_number(0.05 * radial_size) + " m (1/20 of the wall's element size)" + field);
        if (st.field_wall_layers * st.field_mesh_resolution < 1)
          refuse("Spring tube/Field mesh resolution", "x `Field wall layers' must give at least one layer");
      }
    for (double T : sw.table_temperatures)
      if (!(laws::youngs_modulus(st, T) > 0))
        refuse("Spring tube/Modulus temperature coefficient", "makes E(T) <= 0 at " + format_number(T) + " degC (E12)");

    // Pilot stage
    const auto &ps = v.pilot;
    if (!(ps.fixed_orifice_diameter > 0 && ps.fixed_orifice_length > 0 && ps.nozzle_diameter > 0))
      refuse("Pilot stage", "orifice and nozzle dimensions must be > 0");
    if (!(ps.null_gap > 0))
      refuse("Pilot stage/Null gap", "= " + format_number(ps.null_gap) + " m must be > 0");
    if (!(ps.null_gap <= 0.25 * ps.nozzle_diameter))
      refuse("Pilot stage/Null gap", "= " + format_number(ps.null_gap) +
                                       " m must not exceed a quarter of the nozzle diameter, D_N/4 = " +
                                       format_number(0.25 * ps.nozzle_diameter) +
                                       " m, or the nozzle bore instead of the curtain throttles (E32)");
    if (!(ps.land_diameter > ps.nozzle_diameter))
      refuse("Pilot stage/Land diameter", "= " + format_number(ps.land_diameter) +
                                            " m must be above the nozzle diameter " +
                                            format_number(ps.nozzle_diameter) + " m (E22)");
    if (!(ps.nozzle_discharge_coefficient > 0))
      refuse("Pilot stage/Nozzle discharge coefficient", "must be > 0");
    for (double T : sw.table_temperatures)
      {
        const auto g = laws::pilot_stage_geometry(ps, v.armature, v.expansion, T, op.reference_temperature);
        if (!(g.null_gap > 0))
          refuse("Pilot stage/Nozzle seat span", "makes the null gap close at " + format_number(T) + " degC (2.3)");
      }
    if (!(v.armature.pivot_to_nozzle_distance > 0))
      refuse("Armature/Pivot to nozzle distance", "must be > 0");

    // Spool
    const auto &sp = v.spool;
    if (!(sp.control_diameter > 0 && sp.feedback_diameter > 0))
      refuse("Spool/Control diameter", "and `Spool/Feedback diameter' must be > 0");
    if (!(sp.overlap > 0))
      refuse("Spool/Overlap", "= " + format_number(sp.overlap) +
                                " m must be > 0: a critically lapped spool has no unique blocked-port steady "
                                "state in this model");
    if (!(sp.stroke_limit > sp.overlap))
      refuse("Spool/Stroke limit", "= " + format_number(sp.stroke_limit) + " m must exceed the overlap " +
                                     format_number(sp.overlap) + " m");

    // Parts of the dynamic model that the static model uses as well (E36 leakage) or that must be
    // physical whatever runs
    if (!(sp.radial_clearance > 0))
      refuse("Spool/Radial clearance", "= " + format_number(sp.radial_clearance) +
                                         " m must be > 0: the lap leakage sets the blocked brake port's pressure (E36)");
    if (!(v.armature.inertia > 0))
      refuse("Armature/Inertia", "= " + format_number(v.armature.inertia) + " kg*m^2 must be > 0 (E29)");
    if (!(sp.mass > 0))
      refuse("Spool/Mass", "= " + format_number(sp.mass) + " kg must be > 0 (E35)");
    if (!(sp.brake_volume > 0))
      refuse("Spool/Brake volume", "= " + format_number(sp.brake_volume) + " m^3 must be > 0 (E37)");
    if (!(sp.port_volume > 0))
      refuse("Spool/Port volume", "= " + format_number(sp.port_volume) + " m^3 must be > 0 (E37)");
    {
      const double swept = 0.25 * units::pi * sp.control_diameter * sp.control_diameter * sp.stroke_limit;
      if (!(ps.control_cavity_volume > swept))
        refuse("Pilot stage/Control cavity volume",
               "= " + format_number(ps.control_cavity_volume) + " m^3 must exceed the volume the spool end sweeps over "
                 "its stroke, A_v x stroke = " + format_number(swept) + " m^3 (E33: V_0 -+ A_v x_v > 0)");
    }
    if (!(fl.bulk_modulus > 0))
      refuse("Fluid/Bulk modulus", "= " + format_number(fl.bulk_modulus) + " Pa must be > 0 (2.8)");
    for (double T : sw.drift_temperatures)
      if (!(1 - fl.bulk_modulus_temperature_coefficient * (T - op.reference_temperature) > 0))
        refuse("Fluid/Bulk modulus temperature coefficient",
               "= " + format_number(fl.bulk_modulus_temperature_coefficient) + " 1/degC makes beta_e <= 0 at " +
                 format_number(T) + " degC (2.8); it must stay below " +
                 format_number(1 / (T - op.reference_temperature)) + " 1/degC");
    if (v.dynamics.enabled)
      validate_dynamics(v);
    validate_asymmetry(v);
    validate_null_shift_spec(v); // the report holds the drift map against it too
    if (v.tolerances.enabled)
      validate_tolerances(v);

    // Offsets (C8): re-nulling with the hydraulic null removes a hydraulic-null deviation exactly
    if (v.offsets.deviation_target == OffsetParameters::Target::hydraulic_null &&
        v.offsets.nulling == OffsetParameters::Nulling::nulled_at_reference)
      refuse("Offsets/Deviation target", "= hydraulic-null with `Offsets/Nulling' = nulled-at-reference gives zero "
                                         "drift by construction (C8); use as-assembled or another target");
  }
} // namespace servodrift
