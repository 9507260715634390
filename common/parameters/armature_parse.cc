#include "common/parameters/armature.h"

#include "common/parameters/parameter_source.h"

namespace servodrift
{
  using namespace parameters;

  void ArmatureParameters::parse_parameters(ParameterSource &prm)
  {
    prm.enter_subsection(subsection);
    pivot_to_nozzle_distance = prm.get_double("Pivot to nozzle distance");
    inertia = prm.get_double("Inertia");
    damping = prm.get_double("Damping");
    flapper_width = prm.get_double("Flapper width");
    nozzle_contact_stiffness = prm.get_double("Nozzle contact stiffness");
    nozzle_contact_damping_ratio = prm.get_double("Nozzle contact damping ratio");
    prm.leave_subsection();
  }
} // namespace servodrift
