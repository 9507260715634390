#include "common/parameters/spring_tube.h"

#include "common/parameters/parameter_source.h"

namespace servodrift
{
  using namespace parameters;

  void SpringTubeParameters::parse_parameters(ParameterSource &prm)
  {
    prm.enter_subsection(subsection);
    model_level = parse_model_level(prm.get("Model level"));
    youngs_modulus = prm.get_double("Young's modulus");
    reference_temperature = prm.get_double("Reference temperature");
    modulus_temperature_coefficient = prm.get_double("Modulus temperature coefficient");
    poisson_ratio = prm.get_double("Poisson ratio");
    outer_diameter = prm.get_double("Outer diameter");
    inner_diameter = prm.get_double("Inner diameter");
    length = prm.get_double("Length");
    yield_strength = prm.get_double("Yield strength");
    base_flange_diameter = prm.get_double("Base flange diameter");
    base_flange_height = prm.get_double("Base flange height");
    top_collar_diameter = prm.get_double("Top collar diameter");
    top_collar_height = prm.get_double("Top collar height");
    field_element_degree = prm.get_integer("Field element degree");
    field_wall_layers = prm.get_integer("Field wall layers");
    field_aspect_ratio = prm.get_double("Field aspect ratio");
    field_mesh_resolution = prm.get_double("Field mesh resolution");
    prm.leave_subsection();
  }
} // namespace servodrift
