#include "magnetics/torque_motor_field.h"

#include "common/error.h"
#include "common/thermal_laws.h"
#include "common/units.h"

#include <cmath>
#include <limits>

namespace servodrift::embedded
{
  extern const char *const torque_motor_geo;
}

namespace servodrift::magnetics
{
  namespace m = torque_motor_material;

  std::map<std::string, double> torque_motor_geometry_parameters(const ValveDescription &valve, double T,
                                                                 double resolution)
  {
    const auto &tm = valve.torque_motor;
    const auto &alpha = valve.expansion;
    const double T0 = valve.operating.reference_temperature;
    const auto g = laws::torque_motor_geometry(tm, alpha, T, T0); // E6, E7 and the growth of a, l_m
    auto pole = [&](double L) { return laws::expanded(L, alpha.pole_pieces, T, T0); };
    const double mm = 1e3;
    std::map<std::string, double> p;
    p["a"] = g.pivot_to_pole_distance * mm;
    p["lp"] = g.pole_face_length * mm;
    p["Har"] = g.armature_thickness * mm;
    p["La"] = laws::expanded(tm.armature_length, alpha.armature, T, T0) * mm;
    p["Ha"] = laws::expanded(tm.armature_height, alpha.spring_tube, T, T0) * mm;
    p["Hc"] = pole(tm.lower_pole_height) * mm;
    p["tlow"] = pole(tm.upper_pole_thickness) * mm; // H_c' of E7: the plate the magnets stand on
    p["lm"] = g.magnet_length * mm;
    p["hp"] = pole(tm.upper_pole_tip_protrusion) * mm;
    p["tup"] = pole(tm.upper_plate_thickness) * mm;
    p["xm"] = p["a"] + p["lp"] / 2 + pole(tm.field_magnet_clearance) * mm;
    p["wm"] = laws::expanded(tm.field_magnet_width, alpha.magnet, T, T0) * mm;
    p["cin"] = tm.coil_inner_position * mm;
    p["cout"] = tm.coil_outer_position * mm;
    p["cclear"] = tm.coil_clearance * mm;
    p["ch"] = tm.coil_height * mm;
    p["R"] = tm.air_boundary_radius * mm;
    // gmsh's all-quadrilateral subdivision halves every element: ask for half the layers, twice the size
    p["nlayers"] = std::ceil(tm.field_gap_layers * resolution / 2.0);
    p["hgap"] = 2 * 0.15 / resolution;
    p["hiron"] = 2 * 0.6 / resolution;
    p["hmax"] = 2 * (p["R"] / 16) / resolution;

    // validate() has checked the parts against each other at T0; the thermal growth cannot close a gap
    // it has checked at every table temperature, but a caller may ask for another one:
    if (!(g.lower_gap > 0 && g.upper_gap > 0))
      throw InputError("`Torque motor/Armature height' closes a working gap (E6, E7) at " + format_number(T) + " degC");
    return p;
  }

  TorqueMotorFieldModel::TorqueMotorFieldModel(const ValveDescription &valve_, double T, double resolution,
                                               unsigned int refinements,
                                               const std::function<void(std::map<int, Material> &)> &adjust_materials)
    : valve(valve_)
    , temperature(T)
  {
    const auto &tm = valve.torque_motor;
    if (resolution <= 0)
      resolution = tm.field_mesh_resolution;
    const auto parameters = torque_motor_geometry_parameters(valve, T, resolution);
    const PlanarMesh mesh =
      mesh_template({"meshes/torque_motor.geo", embedded::torque_motor_geo, 1e-3, "Torque motor"}, parameters,
                    {{"armature", m::armature},
                     {"pole_pieces", m::pole_pieces},
                     {"magnet", m::magnet},
                     {"coil_upper", m::coil_upper_right},
                     {"coil_lower", m::coil_lower_right},
                     {"air", m::air},
                     {"air_gap", m::air_gap}},
                    {{"outer", 1}}, /*mirror_x=*/true,
                    {{m::coil_upper_right, m::coil_upper_left}, {m::coil_lower_right, m::coil_lower_left}});

    const double T0 = valve.operating.reference_temperature;
    const ArctanBHCurve iron(tm.saturation_polarisation, tm.initial_susceptibility); // 2.2, 1J50
    std::map<int, Material> materials;
    Material armature;
    armature.kind = Material::Kind::nonlinear;
    armature.curve = iron;
    armature.moving = true;
    materials[m::armature] = armature;
    Material pole = armature;
    pole.moving = false;
    materials[m::pole_pieces] = pole;
    Material magnet;
    magnet.kind = Material::Kind::magnet;
    magnet.relative_permeability = tm.recoil_permeability;
    magnet.remanence = {0.0, laws::remanence(tm, T, T0)}; // E8, magnetised from the lower to the upper plate
    materials[m::magnet] = magnet;
    Material air;
    air.morphing = true;
    materials[m::air] = air;
    materials[m::air_gap] = air;
    // Coils: each arm carries half of the net control MMF N_eff i (D7) around the arm, as an
    // out-of-plane current -J = -(N_eff i/2)/A_coil in its upper region and +J in its lower one, on
    // both arms (the mirror image of a coil drives B_x the same way): the control flux runs along -x
    // through the armature, so positive current raises the flux in gaps 1 (lower left) and 4 (upper
    // right), as in E3. The magnets' field is odd in x, the coils' even: T(-theta, -i) = -T(theta, i).
    const double coil_area = tm.coil_height * (tm.coil_outer_position - tm.coil_inner_position);
    const double J = 0.5 * tm.effective_turns() / coil_area;
    auto coil = [&](double sign) {
      Material c;
      c.current_density = sign * J;
      return c;
    };
    materials[m::coil_upper_right] = coil(-1);
    materials[m::coil_lower_right] = coil(+1);
    materials[m::coil_upper_left] = coil(-1);
    materials[m::coil_lower_left] = coil(+1);

    if (adjust_materials)
      adjust_materials(materials);
    Motion motion; // rotation about the pivot at the origin, counterclockwise = theta > 0
    fe = std::make_unique<MagnetostaticProblem>(mesh, materials, motion, tm.field_element_degree,
                                                laws::expanded(tm.model_depth, valve.expansion.pole_pieces, T, T0),
                                                refinements);
  }

  FieldTorque TorqueMotorFieldModel::torque(double angle, double current, bool virtual_work, double tolerance)
  {
    FieldTorque t;
    fe->set_position(angle);
    t.newton = fe->solve(current, tolerance > 0 ? tolerance : valve.torque_motor.newton_tolerance);
    t.stress_tensor = fe->stress_tensor_force();
    t.virtual_work = virtual_work ? fe->virtual_work_force(virtual_work_step) : std::numeric_limits<double>::quiet_NaN();
    return t;
  }

  double TorqueMotorFieldModel::mean_gap_flux_density() const
  {
    return std::abs(fe->mean_flux_density(m::air_gap, 1));
  }

  double TorqueMotorFieldModel::max_armature_flux_density() const
  {
    return fe->max_flux_density(m::armature);
  }
} // namespace servodrift::magnetics
