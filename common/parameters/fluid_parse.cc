#include "common/parameters/fluid.h"

#include "common/parameters/parameter_source.h"

namespace servodrift
{
  using namespace parameters;

  void FluidParameters::parse_parameters(ParameterSource &prm)
  {
    prm.enter_subsection(subsection);
    viscosity_law =
      prm.get("Viscosity law") == "vogel" ? ViscosityLaw::vogel : ViscosityLaw::paper_exponential;
    vogel_a = prm.get_double("Vogel A");
    vogel_b = prm.get_double("Vogel B");
    vogel_c = prm.get_double("Vogel C");
    reference_viscosity = prm.get_double("Reference viscosity");
    viscosity_temperature_coefficient = prm.get_double("Viscosity temperature coefficient");
    minimum_temperature = prm.get_double("Minimum temperature");
    maximum_temperature = prm.get_double("Maximum temperature");
    reference_density = prm.get_double("Reference density");
    density_temperature_coefficient = prm.get_double("Density temperature coefficient");
    bulk_modulus = prm.get_double("Bulk modulus");
    bulk_modulus_temperature_coefficient = prm.get_double("Bulk modulus temperature coefficient");
    vapour_pressure = prm.get_double("Vapour pressure");
    air_release_pressure = prm.get_double("Air release pressure");
    prm.leave_subsection();
  }
} // namespace servodrift
