#!/usr/bin/env bash
# Runs one regression case and compares its text outputs with the references (compare_csv).
set -eu
servodrift=$1 compare=$2 case=$3
here=$(dirname "$0")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$servodrift" run "$here/$case.prm" -o "$work" > /dev/null
for f in tables/spring_tube.csv system/stage_coefficients.csv system/operating_points.csv system/drift_map.csv \
         system/modes.csv system/frequency_response.csv system/step_metrics.csv; do
  echo -n "$f: "
  "$compare" "$here/$case/$(basename "$f")" "$work/$f"
done
