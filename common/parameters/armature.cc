#include "common/parameters/armature.h"

#include "common/parameters/parameter_helpers.h"

namespace servodrift
{
  using namespace parameters;

  void ArmatureParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    prm.declare_entry("Pivot to nozzle distance", "10.0e-3", Patterns::Double(0, 1),
                      "Distance r from the armature pivot to the nozzle axis; x_f = r theta (E29, "
                      "E30). [m]");
    prm.declare_entry("Inertia", "4.0e-7", Patterns::Double(0, 1),
                      "Moment of inertia J_a of armature and flapper about the pivot (E29; dynamics). "
                      "[kg*m^2]");
    prm.declare_entry("Damping", "8e-4", Patterns::Double(0, 1),
                      "Rotational damping B_a of the armature (E29; dynamics). [N*m*s/rad]");
    prm.declare_entry("Flapper width", "1.0e-3", Patterns::Double(0, 1),
                      "Flapper thickness between the two nozzles; enters the thermal change of the "
                      "null gap (2.3). [m]");
    prm.leave_subsection();
  }

  void ArmatureParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    pivot_to_nozzle_distance = prm.get_double("Pivot to nozzle distance");
    inertia = prm.get_double("Inertia");
    damping = prm.get_double("Damping");
    flapper_width = prm.get_double("Flapper width");
    prm.leave_subsection();
  }
} // namespace servodrift
