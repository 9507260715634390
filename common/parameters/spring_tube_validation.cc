// The checks of the spring tube that go beyond one entry's range (validate() in valve_validation.cc
// runs them in its order).
#include "common/error.h"
#include "common/parameters/spring_tube.h"
#include "common/parameters/validation_helpers.h"
#include "common/thermal_laws.h"
#include "common/valve_description.h"

#include <string>
#include <tuple>
#include <utility>

namespace servodrift
{
  using namespace validation;

  void SpringTubeParameters::validate() const
  {
    if (!(outer_diameter > 0 && length > 0))
      refuse("Spring tube/Outer diameter", "and `Spring tube/Length' must be > 0");
    if (!(inner_diameter < outer_diameter))
      refuse("Spring tube/Inner diameter", "= " + format_number(inner_diameter) +
                                             " m must be below the outer diameter " +
                                             format_number(outer_diameter) + " m (wall thickness > 0)");
  }

  void SpringTubeParameters::validate_field_model() const
  {
    const std::string field = " for the field level (`Spring tube/Model level = field')";
    if (!(inner_diameter > 0))
      refuse("Spring tube/Inner diameter", "= " + format_number(inner_diameter) +
                                             " m must be > 0" + field +
                                             ": the n = 1 axisymmetric model needs a bore");
    if (!(poisson_ratio < 0.5))
      refuse("Spring tube/Poisson ratio", "= " + format_number(poisson_ratio) + " must be below 0.5" + field +
                                            " (Lame's lambda is infinite for an incompressible solid)");
    // a flange or collar of height > 0 must stand out of the tube, or there is nothing to mesh
    for (const auto &[part, diameter, height] :
         {std::tuple{"Base flange", base_flange_diameter, base_flange_height},
          std::tuple{"Top collar", top_collar_diameter, top_collar_height}})
      if (height > 0 && !(diameter > outer_diameter))
        refuse(std::string("Spring tube/") + part + " diameter",
               "= " + format_number(diameter) + " m must exceed the outer diameter " +
                 format_number(outer_diameter) + " m when its height is > 0" + field +
                 " (set the height to 0 for none)");
    const double radial_size = 0.5 * (outer_diameter - inner_diameter) / (field_wall_layers * field_mesh_resolution);
    for (const auto &[entry, height] : {std::pair{"Base flange height", base_flange_height},
                                        std::pair{"Top collar height", top_collar_height}})
      if (height > 0 && !(height > 0.05 * radial_size))
        refuse(std::string("Spring tube/") + entry,
               "= " + format_number(height) + " m cannot be meshed: a height above 0 must be at least " +
                 format_number(0.05 * radial_size) + " m (1/20 of the wall's element size)" + field);
    if (field_wall_layers * field_mesh_resolution < 1)
      refuse("Spring tube/Field mesh resolution", "x `Field wall layers' must give at least one layer");
  }

  void SpringTubeParameters::validate(const ValveDescription &v) const
  {
    // the tube stays a spring at every table temperature
    for (double T : v.sweeps.table_temperatures)
      if (!(laws::youngs_modulus(*this, T) > 0))
        refuse("Spring tube/Modulus temperature coefficient", "makes E(T) <= 0 at " + format_number(T) + " degC (E12)");
  }
} // namespace servodrift
