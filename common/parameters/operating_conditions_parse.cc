#include "common/parameters/operating_conditions.h"

#include "common/parameters/parameter_source.h"

namespace servodrift
{
  using namespace parameters;

  void OperatingConditions::parse_parameters(ParameterSource &prm)
  {
    prm.enter_subsection(subsection);
    supply_pressure = prm.get_double("Supply pressure");
    ambient_pressure = prm.get_double("Ambient pressure");
    return_pressure = prm.get_double("Return pressure");
    reference_temperature = prm.get_double("Reference temperature");
    rated_current = prm.get_double("Rated current");
    prm.leave_subsection();
  }
} // namespace servodrift
