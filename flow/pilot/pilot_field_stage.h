#pragma once
// Field level of the flow stage (issue 5): the fixed_orifice and nozzle_flapper tables from the
// finite-volume cases of flow/pilot/pilot_field, with continuation.
//
// Continuation, with the chains shared over the MPI ranks (the tables are the same for any number
// of ranks). The fixed orifice's first case (its lowest pressure difference) is one path over all
// table temperatures, hottest first, each temperature from the hotter one's solution; one rank
// computes it while the others take the nozzle chains, and hands its states to the others. Then one
// chain per table temperature and geometry, hottest first: the orifice from its first case over its
// other pressure differences in increasing order (a second sweep, after the path); the nozzle
// over its gaps, from the null gap outwards (each gap starts from its neighbour's first solution),
// and at each gap over its pressure differences. The orifice's hottest first case and each nozzle
// chain's first case start up laminar (pilot_field.h); every later one starts from a converged
// neighbour.
//
// Each chain also writes, under <output>/flow/, the VTU of the cases `Output/Flow fields' asks for
// (with .pvd collections) and flow/field_cases.csv: every computed case with its diagnostics (flow
// model, iterations, land and jet forces, the lowest absolute pressure and whether it is below the
// vapour pressure, wall y+, the reduced-order values beside it). A case that does not converge is
// flagged (flag 2) and its row carries the reduced-order value, with a warning on stderr; the
// tables add the exact no-flow rows (dp = 0, closed gap; flag 3).
#include "flow/pilot/pilot_stage.h"

namespace servodrift::flow
{
  /// `variant': appended to the cases' file names (flow/<geometry>_cases<variant>.csv).
  PilotTables compute_pilot_field_tables(const ValveDescription &valve, const std::string &variant = "");
} // namespace servodrift::flow
