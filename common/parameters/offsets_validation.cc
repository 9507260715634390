// The checks of the offsets that go beyond one entry's range (validate() in valve_validation.cc runs
// them in its order).
#include "common/parameters/offsets.h"
#include "common/parameters/validation_helpers.h"

namespace servodrift
{
  using namespace validation;

  void OffsetParameters::validate() const
  {
    // C8: re-nulling with the hydraulic null removes a hydraulic-null deviation exactly
    if (deviation_target == Target::hydraulic_null && nulling == Nulling::nulled_at_reference)
      refuse("Offsets/Deviation target", "= hydraulic-null with `Offsets/Nulling' = nulled-at-reference gives zero "
                                         "drift by construction (C8); use as-assembled or another target");
  }
} // namespace servodrift
