// The checks of the spool that go beyond one entry's range (validate() in valve_validation.cc runs
// them in its order).
#include "common/error.h"
#include "common/parameters/spool.h"
#include "common/parameters/validation_helpers.h"

namespace servodrift
{
  using namespace validation;

  void SpoolParameters::validate() const
  {
    if (!(control_diameter > 0 && feedback_diameter > 0))
      refuse("Spool/Control diameter", "and `Spool/Feedback diameter' must be > 0");
    if (!(overlap > 0))
      refuse("Spool/Overlap", "= " + format_number(overlap) +
                                " m must be > 0: a critically lapped spool has no unique blocked-port steady "
                                "state in this model");
    if (!(stroke_limit > overlap))
      refuse("Spool/Stroke limit", "= " + format_number(stroke_limit) + " m must exceed the overlap " +
                                     format_number(overlap) + " m");
    // a part of the dynamic model that the static model uses as well: the lap leakage (E36)
    if (!(radial_clearance > 0))
      refuse("Spool/Radial clearance",
             "= " + format_number(radial_clearance) +
               " m must be > 0: the lap leakage sets the blocked brake port's pressure (E36)");
  }

  void SpoolParameters::validate_dynamic_model() const
  {
    if (!(mass > 0))
      refuse("Spool/Mass", "= " + format_number(mass) + " kg must be > 0 (E35)");
    if (!(brake_volume > 0))
      refuse("Spool/Brake volume", "= " + format_number(brake_volume) + " m^3 must be > 0 (E37)");
    if (!(port_volume > 0))
      refuse("Spool/Port volume", "= " + format_number(port_volume) + " m^3 must be > 0 (E37)");
  }
} // namespace servodrift
