// The checks of the torque motor that go beyond one entry's range (validate() in valve_validation.cc
// runs them in its order).
#include "common/error.h"
#include "common/parameters/torque_motor.h"
#include "common/parameters/validation_helpers.h"
#include "common/thermal_laws.h"
#include "common/units.h"
#include "common/valve_description.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace servodrift
{
  using namespace validation;

  void TorqueMotorParameters::validate() const
  {
    if (!(pivot_to_pole_distance > 0 && pole_face_width > 0 && pole_face_length > 0 && magnet_length > 0 &&
          magnet_width > 0 && magnet_depth > 0))
      refuse("Torque motor", "dimensions (pivot distance, pole face, magnet) must all be > 0");
    // The magnets polarise the motor: without remanence, or with the leakage path shorting them,
    // no flux crosses the working gaps, K_m = 0 and the magnetic null is undefined (E3, E8)
    if (!(remanence * (1 - irreversible_loss) > 0))
      refuse("Torque motor/Remanence", "= " + format_number(remanence) + " T with `Torque motor/Irreversible loss' = " +
                                         format_number(irreversible_loss) +
                                         " leaves the magnets without remanence: no polarising flux, no torque "
                                         "(E8); B_r0 (1 - R_irr) must be > 0");
    if (!(leakage_reluctance > 0))
      refuse("Torque motor/Leakage reluctance", "= 0 shorts the magnets: no flux crosses the working gaps, no torque "
                                                "(E3); it must be > 0");
  }

  void TorqueMotorParameters::validate(const ValveDescription &v) const
  {
    // Gaps open at every temperature and every tabulated angle (E2, E6, E7)
    const auto &op = v.operating;
    const auto &sw = v.sweeps;
    double max_angle = 0;
    for (double a : sw.motor_angles)
      max_angle = std::max(max_angle, std::abs(a));
    for (double T : sw.table_temperatures)
      {
        const auto g = laws::torque_motor_geometry(*this, v.expansion, T, op.reference_temperature);
        if (!(g.lower_gap > 0))
          refuse("Torque motor/Armature height",
                 "gives a closed lower gap g_12 = H_a - H_ar/2 - H_c = " + format_number(g.lower_gap) + " m at " +
                   format_number(T) + " degC (E6); it must be > 0");
        if (!(g.upper_gap > 0))
          refuse("Torque motor/Armature height",
                 "gives a closed upper gap g_34 = H_c' + H_m - h_p - H_a - H_ar/2 = " + format_number(g.upper_gap) +
                   " m at " + format_number(T) + " degC (E7); it must be > 0");
        // the armature's tip, at the outer edge of the pole faces (or its own end), must not touch
        const double tip =
          std::max(g.pivot_to_pole_distance + 0.5 * g.pole_face_length,
                   laws::expanded(armature_length / 2, v.expansion.armature, T, op.reference_temperature));
        const double closing = tip * max_angle;
        const double gap = std::min(g.lower_gap, g.upper_gap);
        if (!(closing < 0.95 * gap))
          refuse("Sweeps/Motor angles",
                 "reach " + format_number(max_angle / units::degree) + " deg, where the armature tip moves " +
                   format_number(closing) + " m of a " + format_number(gap) + " m gap at " + format_number(T) +
                   " degC; keep |angle| below " + format_number(0.95 * gap / tip / units::degree) +
                   " deg, or widen the gap (E6, E7: `Torque motor/Armature height' and the pole and magnet heights)");
      }
    // The torque table covers the angles of the secant K_m and the rated current
    if (!(sw.motor_angles.front() <= -0.1 * units::degree && sw.motor_angles.back() >= 0.1 * units::degree))
      refuse("Sweeps/Motor angles", "must cover -0.1..0.1 deg, where the secant K_m is evaluated (C1)");
    const double i_rated = op.rated_current;
    if (!(sw.motor_currents.front() <= -i_rated && sw.motor_currents.back() >= i_rated))
      refuse("Sweeps/Motor currents", "must cover -rated..rated current, +-" + format_number(i_rated) + " A");
  }

  void TorqueMotorParameters::validate_field_model() const
  {
    // Field model of the torque motor (meshes/torque_motor.geo): parts must not overlap
    const std::string field = " (field model, meshes/torque_motor.geo)";
    const double pole_tip_start = pivot_to_pole_distance - 0.5 * pole_face_length;
    if (!(coil_height > 0))
      refuse("Torque motor/Coil height", "= " + format_number(coil_height) + " m must be > 0: the coil's current "
                                         "density region needs an area" + field);
    if (!(coil_clearance > 0))
      refuse("Torque motor/Coil clearance", "must be > 0: the coil may not touch the moving armature" + field);
    if (!(coil_inner_position < coil_outer_position))
      refuse("Torque motor/Coil inner position", "= " + format_number(coil_inner_position) +
                                                   " m must be below `Torque motor/Coil outer position' = " +
                                                   format_number(coil_outer_position) + " m" + field);
    if (!(coil_outer_position < pole_tip_start))
      refuse("Torque motor/Coil outer position", "= " + format_number(coil_outer_position) +
                                                   " m reaches the pole tips, which start at " +
                                                   format_number(pole_tip_start) + " m" + field);
    const double upper_plate = upper_pole_thickness + magnet_length - armature_height;
    const double lower_plate = upper_pole_thickness - armature_height;
    const double coil_reach = 0.5 * armature_thickness + coil_clearance + coil_height;
    if (!(coil_reach < upper_plate && -coil_reach > lower_plate))
      refuse("Torque motor/Coil height", "= " + format_number(coil_height) +
                                           " m makes a coil region reach a pole plate" + field);
    if (!(field_magnet_clearance > 0.5 * armature_length - pivot_to_pole_distance - 0.5 * pole_face_length))
      refuse("Torque motor/Field magnet clearance", "puts the magnet blocks over the armature's tip" + field);
    if (!(field_magnet_width > 0))
      refuse("Torque motor/Field magnet width", "must be > 0" + field);
    const double half_size = std::max(pivot_to_pole_distance + 0.5 * pole_face_length + field_magnet_clearance +
                                        field_magnet_width,
                                      armature_height + upper_plate_thickness);
    if (!(air_boundary_radius > 1.5 * half_size))
      refuse("Torque motor/Air boundary radius", "= " + format_number(air_boundary_radius) +
                                                   " m must enclose the motor with room, at least " +
                                                   format_number(1.5 * half_size) + " m" + field);
  }
} // namespace servodrift
