#include "common/parameters/offsets.h"

#include "common/parameters/parameter_source.h"
#include "common/units.h"

namespace servodrift
{
  using namespace parameters;

  void OffsetParameters::parse_parameters(ParameterSource &prm)
  {
    prm.enter_subsection(subsection);
    spring_tube_rest_angle = prm.get_double("Spring tube rest angle") * units::degree;
    magnetic_null = prm.get_double("Magnetic null") * units::degree;
    hydraulic_null = prm.get_double("Hydraulic null");
    const std::string target = prm.get("Deviation target");
    deviation_target = target == "magnetic-null"          ? Target::magnetic_null :
                       target == "spring-tube-rest-angle" ? Target::spring_tube_rest_angle :
                                                            Target::hydraulic_null;
    nulling = prm.get("Nulling") == "as-assembled" ? Nulling::as_assembled : Nulling::nulled_at_reference;
    prm.leave_subsection();
  }
} // namespace servodrift
