#pragma once
// The "Dynamics" section of report.md: a table of bandwidth, -90 degree frequency, armature mode,
// overshoot and settling time per temperature, the checks, the large-signal study and, for the paper
// preset, the fixed-time readings of model.md C9.
#include "common/valve_description.h"
#include "system/dynamics.h"

#include <ostream>

namespace servodrift::system
{
  void dynamics_section(std::ostream &out, const ValveDescription &valve, const DynamicsResults &results);
} // namespace servodrift::system
