#!/usr/bin/env bash
# The tables and drift maps of `mpirun -np 2' are byte-identical to the serial run's.
set -eu
servodrift=$1 mpirun=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# the field-level torque motor on a coarse mesh, two temperatures
sets=(--set "Output/Plots=false" --set "Torque motor/Field mesh resolution=0.5"
      --set "Sweeps/Table temperatures=40, 120" --set "Sweeps/Drift temperatures=40, 80, 120"
      --set "Sweeps/Motor currents=-0.02, 0, 0.02"
      --set "Sweeps/Deviation angles=-0.05, -0.02, 0, 0.02, 0.05")
"$servodrift" run "${sets[@]}" -o "$work/serial" > /dev/null
"$mpirun" -np 2 "$servodrift" run "${sets[@]}" -o "$work/mpi" > "$work/mpi.log" 2>&1 || { cat "$work/mpi.log"; exit 1; }
grep -q "on 2 ranks" "$work/mpi.log" || { echo "mpirun did not start 2 ranks"; cat "$work/mpi.log"; exit 1; }
n=0
for f in tables/torque_motor.csv tables/spring_tube.csv tables/fixed_orifice.csv tables/nozzle_flapper.csv \
         tables/fits.json system/drift_map.csv system/stage_coefficients.csv system/operating_points.csv; do
  cmp "$work/serial/$f" "$work/mpi/$f"
  n=$((n + 1))
done
echo "ok: $n files byte-identical on 1 and 2 ranks"
