#include "common/parameters/thermal_expansion.h"

#include "common/parameters/parameter_source.h"

namespace servodrift
{
  using namespace parameters;

  void ThermalExpansion::parse_parameters(ParameterSource &prm)
  {
    prm.enter_subsection(subsection);
    spring_tube = prm.get_double("Spring tube");
    armature = prm.get_double("Armature");
    pole_pieces = prm.get_double("Pole pieces");
    magnet = prm.get_double("Magnet");
    body = prm.get_double("Body");
    nozzle = prm.get_double("Nozzle");
    flapper = prm.get_double("Flapper");
    spool = prm.get_double("Spool");
    prm.leave_subsection();
  }
} // namespace servodrift
