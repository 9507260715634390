#pragma once
// The flow stage: computes the fixed_orifice table (temperature x pressure difference) and the
// nozzle_flapper table (temperature x gap x pressure difference) at the model level chosen by
// `Pilot stage/Model level'.
#include "common/table.h"
#include "common/valve_description.h"

namespace servodrift::flow
{
  struct PilotTables
  {
    Table fixed_orifice;
    Table nozzle_flapper;
  };

  /// Both tables at the model level of the valve description.
  PilotTables compute_pilot_tables(const ValveDescription &valve);
  /// Computes both tables and writes them under tables/ (rank 0).
  void run(const ValveDescription &valve);
} // namespace servodrift::flow
