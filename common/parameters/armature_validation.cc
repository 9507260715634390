// The checks of the armature that go beyond one entry's range (validate() in valve_validation.cc
// runs them in its order).
#include "common/error.h"
#include "common/parameters/armature.h"
#include "common/parameters/validation_helpers.h"

namespace servodrift
{
  using namespace validation;

  void ArmatureParameters::validate() const
  {
    if (!(pivot_to_nozzle_distance > 0))
      refuse("Armature/Pivot to nozzle distance", "must be > 0");
  }

  void ArmatureParameters::validate_dynamic_model() const
  {
    if (!(inertia > 0))
      refuse("Armature/Inertia", "= " + format_number(inertia) + " kg*m^2 must be > 0 (E29)");
  }
} // namespace servodrift
