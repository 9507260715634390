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
    prm.declare_entry("Nozzle contact stiffness", "1e8", Patterns::Double(1e3, 1e13),
                      "Stiffness K_c of the stop that a nozzle tip makes for the flapper (dynamics: the "
                      "flapper on a nozzle is a contact, not a failure; the gap never goes negative). "
                      "The static model uses it too, so a flapper pressed on a nozzle sinks in by "
                      "force/K_c. [N/m]");
    prm.declare_entry("Nozzle contact damping ratio", "0.7", Patterns::Double(0, 10),
                      "Damping ratio of the nozzle contact: c_c = 2 zeta_c sqrt(K_c J_a/r^2), active "
                      "only while in contact and never pulling (dynamics). [1]");
    prm.leave_subsection();
  }
} // namespace servodrift
