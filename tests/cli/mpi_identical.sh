#!/usr/bin/env bash
# The outputs of `mpirun -np 2' are byte-identical to the serial run's.
# usage: mpi_identical.sh servodrift mpirun [whole-chain|flow-field|tolerances]
#   whole-chain (default): `servodrift run' with the field-level torque motor on a coarse mesh and the
#     reduced-order pilot stage (the field-level flow is the other case), two temperatures; its four
#     tables, the fits, the drift maps and the dynamics (a temperature's linear analyses and steps,
#     and each temperature and sine frequency, are cases shared over the ranks).
#   flow-field: `servodrift flow' at the field level. One rank computes the fixed orifice's first
#     cases over temperature (one path, hottest first) beside the nozzle chains and hands their fields
#     to the others; the orifice chains that go on from them are shared over the ranks
#     (flow/pilot/pilot_field_stage.h). A small sweep on a coarse mesh: two temperatures, two
#     orifice pressure levels (so each orifice chain goes on from the path's state), one gap at one
#     pressure level; every case must converge.
#   tolerances: `servodrift tolerances' on reduced-order tables (made once, serially): the valves of
#     the Monte Carlo and of the Sobol' design are cases shared over the ranks; the draws, the
#     statistics and the bootstrap are seeded.
set -eu
servodrift=$1 mpirun=$2 which=${3:-whole-chain}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
case "$which" in
  whole-chain)
    command=run
    sets=(--set "Output/Plots=false" --set "Torque motor/Field mesh resolution=0.5"
          --set "Pilot stage/Model level=reduced-order"
          --set "Sweeps/Table temperatures=40, 120" --set "Sweeps/Drift temperatures=40, 80, 120"
          --set "Sweeps/Motor currents=-0.02, 0, 0.02"
          --set "Sweeps/Deviation angles=-0.05, -0.02, 0, 0.02, 0.05"
          --set "Dynamics/Sine frequencies=20, 200" --set "Dynamics/Sine amplitudes=0.05, 0.5"
          --set "Dynamics/Frequency points=40")
    files=(tables/torque_motor.csv tables/spring_tube.csv tables/fixed_orifice.csv tables/nozzle_flapper.csv
           tables/fits.json system/drift_map.csv system/stage_coefficients.csv system/operating_points.csv
           system/modes.csv system/frequency_response.csv system/step_response.csv system/step_metrics.csv
           system/sine_response.csv system/dynamics_summary.csv) ;;
  flow-field)
    command=flow
    sets=(--set "Pilot stage/Model level=field" --set "Pilot stage/Field mesh/Resolution=0.6"
          --set "Output/Flow fields=none" --set "Output/Progress=none"
          --set "Sweeps/Table temperatures=40, 60" --set "Sweeps/Drift temperatures=40, 60"
          --set "Sweeps/Field orifice pressure fractions=0.05, 0.25" --set "Sweeps/Field gap fractions=1"
          --set "Sweeps/Field nozzle pressure fractions=0.5")
    files=(tables/fixed_orifice.csv tables/nozzle_flapper.csv) ;;
  tolerances)
    command=tolerances
    sets=(--set "Output/Plots=false" --set "Torque motor/Model level=reduced-order"
          --set "Pilot stage/Model level=reduced-order" --set "Spring tube/Model level=reduced-order"
          --set "Sweeps/Drift temperatures=40, 80, 120" --set "Sweeps/Deviation angles=0"
          --set "Tolerances/Samples=150" --set "Tolerances/Sobol base samples=64"
          --set "Tolerances/Left orifice diameter/Distribution=normal"
          --set "Tolerances/Left orifice diameter/Standard deviation=1e-6"
          --set "Tolerances/Magnetic null/Distribution=uniform"
          --set "Tolerances/Magnetic null/Lower bound=-2e-4" --set "Tolerances/Magnetic null/Upper bound=2e-4")
    for d in serial mpi; do
      "$servodrift" run "${sets[@]}" -o "$work/$d" > "$work/tables.log" 2>&1 || { cat "$work/tables.log"; exit 1; }
    done
    files=(system/tolerance_samples.csv system/tolerance_summary.csv system/sobol_indices.csv) ;;
  *) echo "unknown case '$which'"; exit 2 ;;
esac
"$servodrift" "$command" "${sets[@]}" -o "$work/serial" > "$work/serial.log" 2>&1 || { cat "$work/serial.log"; exit 1; }
"$mpirun" -np 2 "$servodrift" "$command" "${sets[@]}" -o "$work/mpi" > "$work/mpi.log" 2>&1 || { cat "$work/mpi.log"; exit 1; }
grep -q "on 2 ranks" "$work/mpi.log" || { echo "mpirun did not start 2 ranks"; cat "$work/mpi.log"; exit 1; }
if [ "$which" = flow-field ]; then
  for f in tables/fixed_orifice.csv tables/nozzle_flapper.csv; do
    grep -q "flow/field" "$work/serial/$f" || { echo "$f: not from the field level"; exit 1; }
  done
  for f in flow/fixed_orifice_cases.csv flow/nozzle_flapper_cases.csv; do # flag 0: the last column
    flagged=$(grep -v '^#' "$work/serial/$f" | tail -n +2 | awk -F, '$NF != 0' | wc -l)
    [ "$flagged" = 0 ] || { echo "$f: $flagged flagged cases"; cat "$work/serial/$f"; exit 1; }
  done
fi
for f in "${files[@]}"; do
  cmp "$work/serial/$f" "$work/mpi/$f"
done
echo "ok: ${#files[@]} files byte-identical on 1 and 2 ranks ($which)"
