#pragma once
// The flow stage: computes the fixed_orifice table (temperature x pressure difference) and the
// nozzle_flapper table (temperature x gap x pressure difference) at the model level chosen by
// `Pilot stage/Model level'.
#include "common/table.h"
#include "common/valve_description.h"

namespace servodrift::flow
{
  Table compute_fixed_orifice_table(const ValveDescription &valve);
  Table compute_nozzle_flapper_table(const ValveDescription &valve);
  /// Computes both tables and writes them under tables/ (rank 0).
  void run(const ValveDescription &valve);
} // namespace servodrift::flow
