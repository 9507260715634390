#include "common/parameters/spool.h"

#include "common/parameters/parameter_source.h"

namespace servodrift
{
  using namespace parameters;

  void SpoolParameters::parse_parameters(ParameterSource &prm)
  {
    prm.enter_subsection(subsection);
    control_diameter = prm.get_double("Control diameter");
    feedback_diameter = prm.get_double("Feedback diameter");
    mass = prm.get_double("Mass");
    spring_rate = prm.get_double("Spring rate");
    spring_preload = prm.get_double("Spring preload");
    area_gradient = prm.get_double("Area gradient");
    overlap = prm.get_double("Overlap");
    stroke_limit = prm.get_double("Stroke limit");
    discharge_coefficient = prm.get_double("Discharge coefficient");
    jet_angle = prm.get_double("Jet angle");
    radial_clearance = prm.get_double("Radial clearance");
    land_length = prm.get_double("Land length");
    brake_volume = prm.get_double("Brake volume");
    brake_port = prm.get("Brake port") == "blocked-port" ? BrakePort::blocked_port : BrakePort::brake_volume;
    port_volume = prm.get_double("Port volume");
    minimum_leak_length = prm.get_double("Minimum leak length");
    laminar_transition_number = prm.get_double("Laminar transition number");
    stop_stiffness = prm.get_double("Stop stiffness");
    stop_damping_ratio = prm.get_double("Stop damping ratio");
    prm.leave_subsection();
  }
} // namespace servodrift
