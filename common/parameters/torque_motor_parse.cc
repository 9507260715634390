#include "common/parameters/torque_motor.h"

#include "common/parameters/parameter_source.h"

namespace servodrift
{
  using namespace parameters;

  void TorqueMotorParameters::parse_parameters(ParameterSource &prm)
  {
    prm.enter_subsection(subsection);
    model_level = parse_model_level(prm.get("Model level"));
    turns_per_coil = prm.get_integer("Turns per coil");
    series_aiding = prm.get("Coil connection") == "series-aiding";
    pivot_to_pole_distance = prm.get_double("Pivot to pole-face distance");
    pole_face_width = prm.get_double("Pole face width");
    pole_face_length = prm.get_double("Pole face length");
    fringing_expanded_area = prm.get("Gap fringing") == "expanded-area";
    armature_thickness = prm.get_double("Armature thickness");
    armature_width = prm.get_double("Armature width");
    armature_length = prm.get_double("Armature length");
    armature_height = prm.get_double("Armature height");
    lower_pole_height = prm.get_double("Lower pole height");
    upper_pole_thickness = prm.get_double("Upper pole thickness");
    upper_pole_tip_protrusion = prm.get_double("Upper pole tip protrusion");
    magnet_length = prm.get_double("Magnet length");
    magnet_width = prm.get_double("Magnet width");
    magnet_depth = prm.get_double("Magnet depth");
    number_of_magnets = prm.get_integer("Number of magnets");
    remanence = prm.get_double("Remanence");
    remanence_temperature_coefficient = prm.get_double("Remanence temperature coefficient");
    irreversible_loss = prm.get_double("Irreversible loss");
    recoil_permeability = prm.get_double("Recoil permeability");
    leakage_reluctance = prm.get_double("Leakage reluctance");
    pole_piece_reluctance = prm.get_double("Pole piece reluctance");
    armature_reluctance = prm.get_double("Armature reluctance");
    saturation_polarisation = prm.get_double("Saturation polarisation");
    initial_susceptibility = prm.get_double("Initial susceptibility");
    model_depth = prm.get_double("Model depth");
    paper_magnetic_spring = prm.get("Magnetic spring law") == "paper-fit";
    field_element_degree = prm.get_integer("Field element degree");
    field_mesh_resolution = prm.get_double("Field mesh resolution");
    field_gap_layers = prm.get_integer("Field gap layers");
    field_magnet_width = prm.get_double("Field magnet width");
    field_magnet_clearance = prm.get_double("Field magnet clearance");
    upper_plate_thickness = prm.get_double("Upper plate thickness");
    coil_inner_position = prm.get_double("Coil inner position");
    coil_outer_position = prm.get_double("Coil outer position");
    coil_height = prm.get_double("Coil height");
    coil_clearance = prm.get_double("Coil clearance");
    air_boundary_radius = prm.get_double("Air boundary radius");
    newton_tolerance = prm.get_double("Newton tolerance");
    coil_resistance = prm.get_double("Coil resistance");
    coil_resistance_temperature_coefficient = prm.get_double("Coil resistance temperature coefficient");
    coil_inductance = prm.get_double("Coil inductance");
    voltage_drive = prm.get("Coil drive") == "voltage";
    prm.leave_subsection();
  }
} // namespace servodrift
