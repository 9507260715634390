// The checks of the fluid that go beyond one entry's range (validate() in valve_validation.cc runs
// them in its order).
#include "common/error.h"
#include "common/parameters/fluid.h"
#include "common/parameters/validation_helpers.h"
#include "common/thermal_laws.h"
#include "common/valve_description.h"

#include <cmath>
#include <string>
#include <vector>

namespace servodrift
{
  using namespace validation;

  void FluidParameters::validate() const
  {
    // Temperatures inside the oil law's window (E16 is singular at T = -C)
    if (!(minimum_temperature < maximum_temperature))
      refuse("Fluid/Minimum temperature", "= " + format_number(minimum_temperature) +
                                            " degC must be below `Fluid/Maximum temperature' = " +
                                            format_number(maximum_temperature) + " degC");
    if (viscosity_law == ViscosityLaw::vogel && !(minimum_temperature > -vogel_c))
      refuse("Fluid/Minimum temperature", "= " + format_number(minimum_temperature) +
                                            " degC must be above -`Fluid/Vogel C' = " +
                                            format_number(-vogel_c) + " degC, where E16 is singular");
  }

  void FluidParameters::validate(const ValveDescription &v) const
  {
    // Every temperature the valve is evaluated at inside the oil law's window
    const auto &op = v.operating;
    const auto &sw = v.sweeps;
    auto check_window = [&](const std::vector<double> &list, const std::string &entry) {
      for (double T : list)
        if (!(T >= minimum_temperature && T <= maximum_temperature))
          refuse(entry, "contains " + format_number(T) + " degC, outside the oil viscosity law's window [" +
                          format_number(minimum_temperature) + ", " + format_number(maximum_temperature) +
                          "] degC (`Fluid/Minimum temperature', `Fluid/Maximum temperature')");
    };
    check_window(sw.table_temperatures, "Sweeps/Table temperatures");
    check_window(sw.drift_temperatures, "Sweeps/Drift temperatures");
    check_window({op.reference_temperature}, "Operating conditions/Reference temperature");
    // The oil law gives a positive, finite viscosity and density wherever a table is made (E14-E16)
    const laws::Oil oil(*this, op.reference_temperature);
    for (double T : sw.table_temperatures)
      {
        const double nu = oil.kinematic_viscosity(T).value, rho = oil.density(T).value;
        if (!(nu > 0 && std::isfinite(nu) && nu < 1))
          refuse(viscosity_law == ViscosityLaw::vogel ? "Fluid/Vogel A" : "Fluid/Reference viscosity",
                 "and the other constants of the viscosity law give nu = " + format_number(nu) + " m^2/s at " +
                   format_number(T) + " degC; it must lie in (0, 1) m^2/s at every table temperature (E14, E16)");
        if (!(rho > 0 && std::isfinite(rho)))
          refuse("Fluid/Density temperature coefficient",
                 "= " + format_number(density_temperature_coefficient) + " 1/degC gives a density of " +
                   format_number(rho) + " kg/m^3 at " + format_number(T) + " degC; it must stay > 0 (E15)");
      }
  }

  void FluidParameters::validate_dynamic_model(const ValveDescription &v) const
  {
    // the oil's compliance of the dynamic model, beta_e(T) > 0 at every drift temperature
    const auto &op = v.operating;
    if (!(bulk_modulus > 0))
      refuse("Fluid/Bulk modulus", "= " + format_number(bulk_modulus) + " Pa must be > 0 (2.8)");
    for (double T : v.sweeps.drift_temperatures)
      if (!(1 - bulk_modulus_temperature_coefficient * (T - op.reference_temperature) > 0))
        refuse("Fluid/Bulk modulus temperature coefficient",
               "= " + format_number(bulk_modulus_temperature_coefficient) + " 1/degC makes beta_e <= 0 at " +
                 format_number(T) + " degC (2.8); it must stay below " +
                 format_number(1 / (T - op.reference_temperature)) + " 1/degC");
  }
} // namespace servodrift
