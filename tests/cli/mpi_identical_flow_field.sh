#!/usr/bin/env bash
# The field-level flow stage's tables of `mpirun -np 2' are byte-identical to the serial run's: every
# rank computes the fixed orifice's first cases over temperature (one path, hottest first) and the
# chains that go on from them are shared over the ranks (flow/pilot_field_stage.h). A small sweep on a
# coarse mesh: two temperatures, two orifice pressure levels (so each orifice chain goes on from the
# path's state), one gap at one pressure level.
set -eu
servodrift=$1 mpirun=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sets=(--set "Pilot stage/Model level=field" --set "Pilot stage/Field mesh resolution=0.6"
      --set "Output/Flow fields=none" --set "Output/Progress=none"
      --set "Sweeps/Table temperatures=40, 60" --set "Sweeps/Drift temperatures=40, 60"
      --set "Sweeps/Field orifice pressure fractions=0.05, 0.25" --set "Sweeps/Field gap fractions=1"
      --set "Sweeps/Field nozzle pressure fractions=0.5")
"$servodrift" flow "${sets[@]}" -o "$work/serial" > "$work/serial.log" 2>&1 || { cat "$work/serial.log"; exit 1; }
"$mpirun" -np 2 "$servodrift" flow "${sets[@]}" -o "$work/mpi" > "$work/mpi.log" 2>&1 || { cat "$work/mpi.log"; exit 1; }
grep -q "on 2 ranks" "$work/mpi.log" || { echo "mpirun did not start 2 ranks"; cat "$work/mpi.log"; exit 1; }
for f in tables/fixed_orifice.csv tables/nozzle_flapper.csv; do
  grep -q "flow/field" "$work/serial/$f" || { echo "$f: not from the field level"; exit 1; }
  cmp "$work/serial/$f" "$work/mpi/$f"
done
# every case converged (flag 0 in the last column of the case summaries) and the same on both runs
for f in flow/fixed_orifice_cases.csv flow/nozzle_flapper_cases.csv; do
  flagged=$(grep -v '^#' "$work/serial/$f" | tail -n +2 | awk -F, '$NF != 0' | wc -l)
  [ "$flagged" = 0 ] || { echo "$f: $flagged flagged cases"; cat "$work/serial/$f"; exit 1; }
done
echo "ok: the field-level flow tables are byte-identical on 1 and 2 ranks"
