#!/usr/bin/env bash
# A whole run of a parameter file: exit 0, every output present, no NaN anywhere.
set -eu
servodrift=$1 input=$2
shift 2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$servodrift" run "$input" -o "$work/out" --set "Output/Plots=false" "$@" > "$work/log" 2>&1 || { cat "$work/log"; exit 1; }
for f in parameters.prm report.md tables/torque_motor.csv tables/spring_tube.csv tables/fixed_orifice.csv \
         tables/nozzle_flapper.csv tables/fits.json system/drift_map.csv system/stage_coefficients.csv; do
  [ -s "$work/out/$f" ] || { echo "missing $f"; exit 1; }
done
if grep -rliE '(^|[^a-z])nan([^a-z]|$)' "$work/out" --include='*.csv' --include='*.json'; then echo "NaN in output"; exit 1; fi
if grep -rl -- '-nan\|inf,' "$work/out" --include='*.csv'; then echo "non-finite value in output"; exit 1; fi
echo "ok"
