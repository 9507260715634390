#!/usr/bin/env bash
# `servodrift dynamics' on tables already in <dir>/tables (made by a run without the dynamics):
# exit 0, the dynamics' files and report section written, the tables untouched.
set -eu
servodrift=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
common=(--set "Output/Plots=false" --set "Output/Progress=none" --set "Torque motor/Model level=reduced-order"
        --set "Pilot stage/Model level=reduced-order" --set "Spring tube/Model level=reduced-order"
        --set "Sweeps/Drift temperatures=40, 120" --set "Sweeps/Deviation angles=0")
"$servodrift" run -o "$work/out" "${common[@]}" --set "Dynamics/Enabled=false" > "$work/log" 2>&1 || { cat "$work/log"; exit 1; }
[ ! -e "$work/out/system/modes.csv" ] || { echo "the run without the dynamics wrote modes.csv"; exit 1; }
grep -q "Not computed in this run" "$work/out/report.md" || { echo "report.md does not say the dynamics were not run"; exit 1; }
sum=$(cat "$work/out/tables/"*.csv | sha256sum)
"$servodrift" dynamics -o "$work/out" "${common[@]}" --set "Dynamics/Sine frequencies=20, 200" \
  --set "Dynamics/Enabled=false" > "$work/log" 2>&1 || { cat "$work/log"; exit 1; }
for f in modes.csv frequency_response.csv step_response.csv step_metrics.csv sine_response.csv dynamics_summary.csv; do
  [ -s "$work/out/system/$f" ] || { echo "missing system/$f"; exit 1; }
done
grep -q "^| 120 |" "$work/out/report.md" || { echo "no dynamics table in report.md"; exit 1; }
[ "$sum" = "$(cat "$work/out/tables/"*.csv | sha256sum)" ] || { echo "the tables changed"; exit 1; }
echo ok
