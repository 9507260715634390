#pragma once
// Field level of the flow stage (issue 5): the fixed_orifice and nozzle_flapper tables from the
// finite-volume cases of flow/pilot_field, with continuation.
//
// Continuation paths, shared over the MPI ranks as one pool (the tables are the same for any
// number of ranks): the fixed orifice is one path over all table temperatures, hottest first, at
// each temperature over its pressure differences in increasing order, each temperature's first case
// starting from the hotter one's first solution; the nozzle is one chain per table temperature, over
// its gaps from the null gap outwards (each gap starts from its neighbour's first solution), and at
// each gap over its pressure differences. The first case of the orifice's path and of each nozzle
// chain starts up laminar (pilot_field.h); every later one starts from a converged neighbour.
//
// Each chain also writes, under <output>/flow/, the VTU of the cases `Output/Flow fields' asks for
// (with .pvd collections) and flow/field_cases.csv: every computed case with its diagnostics (flow
// model, iterations, land and jet forces, the lowest absolute pressure and whether it is below the
// vapour pressure, wall y+, the reduced-order values beside it). A case that does not converge is
// flagged (flag 2) and its row carries the reduced-order value, with a warning on stderr; the
// tables add the exact no-flow rows (dp = 0, closed gap; flag 3).
#include "flow/pilot_stage.h"

namespace servodrift::flow
{
  PilotTables compute_pilot_field_tables(const ValveDescription &valve);
} // namespace servodrift::flow
