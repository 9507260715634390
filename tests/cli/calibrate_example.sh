#!/usr/bin/env bash
# `servodrift calibrate' end to end: data made by the model with a magnetic null of 0.02 deg (the
# drift map's null-shift currents), the fit from 0 finds it to 1e-6 relative, writes its files
# without NaN, and the calibrated valve file reads back with the estimate.
set -eu
servodrift=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
sets=(--set "Torque motor/Model level=reduced-order" --set "Spring tube/Model level=reduced-order"
      --set "Pilot stage/Model level=reduced-order" --set Dynamics/Enabled=false --set Output/Plots=false
      --set Output/Progress=none --set "Sweeps/Deviation angles=0" --set "Sweeps/Drift temperatures=40, 60, 80, 100, 120")
"$servodrift" run -o out "${sets[@]}" --set "Offsets/Magnetic null=0.02" > log 2>&1 || { cat log; exit 1; }
{ echo "temperature[degC],current[A],null_shift_current[A]"
  grep -v '^#' out/system/drift_map.csv | tail -n +2 | awk -F, '$1 > 40 { print $1 ",0," $11 }'; } > measured.csv
[ "$(wc -l < measured.csv)" = 5 ] || { echo "measured.csv:"; cat measured.csv; exit 1; }
"$servodrift" calibrate measured.csv -o out "${sets[@]}" --free "Offsets/Magnetic null" > log 2>&1 || { cat log; exit 1; }
for f in calibration/result.json calibration/fit.csv calibration/calibrated.prm report.md; do
  [ -s "out/$f" ] || { echo "missing $f"; exit 1; }
done
estimate=$(grep -m1 '"estimate"' out/calibration/result.json | sed 's/.*: *\([^,]*\),*/\1/')
awk -v e="$estimate" 'BEGIN { d = (e - 0.02) / 0.02; if (d < 0) d = -d; exit !(d < 1e-6) }' ||
  { echo "estimate $estimate, expected 0.02"; exit 1; }
grep -q "^## Calibration" out/report.md || { echo "no Calibration section in report.md"; exit 1; }
if grep -rliE '(^|,)-?(nan|inf)(,|$)' out/calibration --include='*.csv'; then echo "non-finite value in output"; exit 1; fi
"$servodrift" params out/calibration/calibrated.prm | grep -q "set Magnetic null *= 0.0199999\|set Magnetic null *= 0.02" ||
  { echo "calibrated.prm does not carry the estimate"; grep "Magnetic null" out/calibration/calibrated.prm; exit 1; }
echo "ok: estimate $estimate deg"
