#!/usr/bin/env bash
# The finite-volume solver's library (servodrift_fv, flow/fv/) knows nothing of the valve: none of the
# files of its directory includes the valve description, the pilot stage's parameters or the pilot
# stage's files (flow/pilot/), and every source the library compiles is one of them.
# Usage: fv_knows_no_valve.sh <flow/fv dir> <source>...
set -euo pipefail
dir=$1
shift
for source in "$@"; do
  [ -f "$dir/$(basename "$source")" ] || { echo "servodrift_fv compiles $source, which is not in $dir"; exit 1; }
done
files=("$dir"/*.h "$dir"/*.cc)
if grep -nE '#include "(common/valve_description|common/parameters/pilot|common/pilot|flow/pilot/)' "${files[@]}"; then
  echo "the finite-volume solver includes the valve's or the pilot stage's headers (above)"
  exit 1
fi
echo "${#files[@]} files of servodrift_fv ($dir) include nothing of the valve"
