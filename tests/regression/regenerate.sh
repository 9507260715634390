#!/usr/bin/env bash
# Regenerates the reference outputs of the regression cases. Run only when a change of the numbers
# is intended, and say why in the commit message:
#   tests/regression/regenerate.sh build/servodrift
set -eu
servodrift=$(realpath "$1")
cd "$(dirname "$0")"
for case in rv1_coarse; do
  work=$(mktemp -d)
  "$servodrift" run "$case.prm" -o "$work" > /dev/null
  mkdir -p "$case"
  for f in tables/spring_tube.csv system/stage_coefficients.csv system/operating_points.csv system/drift_map.csv \
         system/modes.csv system/frequency_response.csv system/step_metrics.csv; do
    cp "$work/$f" "$case/$(basename "$f")"
  done
  rm -rf "$work"
done
