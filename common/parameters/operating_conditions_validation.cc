// The checks of the operating conditions that go beyond one entry's range (validate() in
// valve_validation.cc runs them in its order).
#include "common/error.h"
#include "common/parameters/operating_conditions.h"
#include "common/parameters/validation_helpers.h"

namespace servodrift
{
  using namespace validation;

  void OperatingConditions::validate() const
  {
    if (!(rated_current > 0))
      refuse("Operating conditions/Rated current", "= " + format_number(rated_current) +
                                                     " A must be > 0: drifts are given in % of it (D7, D9)");
    if (!(return_pressure < supply_pressure))
      refuse("Operating conditions/Return pressure",
             "= " + format_number(return_pressure) + " Pa must be below the supply pressure " +
               format_number(supply_pressure) + " Pa");
  }
} // namespace servodrift
