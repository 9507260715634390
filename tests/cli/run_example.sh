#!/usr/bin/env bash
# A whole run of a parameter file: exit 0, every output present (the dynamics' too), no NaN anywhere.
set -eu
servodrift=$1 input=$2
shift 2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$servodrift" run "$input" -o "$work/out" --set "Output/Plots=false" "$@" > "$work/log" 2>&1 || { cat "$work/log"; exit 1; }
for f in parameters.prm report.md tables/torque_motor.csv tables/spring_tube.csv tables/fixed_orifice.csv \
         tables/nozzle_flapper.csv tables/fits.json system/drift_map.csv system/stage_coefficients.csv \
         system/modes.csv system/frequency_response.csv system/step_response.csv system/step_metrics.csv \
         system/sine_response.csv system/dynamics_summary.csv; do
  [ -s "$work/out/$f" ] || { echo "missing $f"; exit 1; }
done
# a fixed-time study asked for is written and in the report
if grep -q "^ *set Fixed-time study *= *true" "$work/out/parameters.prm"; then
  [ -s "$work/out/system/fixed_time_study.csv" ] || { echo "missing system/fixed_time_study.csv"; exit 1; }
  grep -q "Fixed-time readings of the start-up" "$work/out/report.md" || { echo "no fixed-time section in report.md"; exit 1; }
fi
grep -q "^## Dynamics" "$work/out/report.md" || { echo "no Dynamics section in report.md"; exit 1; }
if grep -rliE '(^|[^a-z])nan([^a-z]|$)' "$work/out" --include='*.csv' --include='*.json'; then echo "NaN in output"; exit 1; fi
if grep -rl --include='*.csv' -e '-nan' -e 'inf,' "$work/out"; then echo "non-finite value in output"; exit 1; fi
echo "ok"
