#!/usr/bin/env bash
# The finite-volume solver's library (servodrift_fv, flow/CMakeLists.txt) knows nothing of the valve:
# none of its sources, nor the headers of the same name, includes the valve description, the pilot
# stage's parameters or the pilot stage's files. Usage: fv_knows_no_valve.sh <flow dir> <source>...
set -euo pipefail
dir=$1
shift
files=()
for source in "$@"; do
  files+=("$dir/$source")
  header="$dir/${source%.cc}.h"
  [ -f "$header" ] && files+=("$header")
done
if grep -nE '#include "(common/valve_description|common/parameters/pilot|common/pilot|flow/pilot)' "${files[@]}"; then
  echo "the finite-volume solver includes the valve's or the pilot stage's headers (above)"
  exit 1
fi
echo "${#files[@]} files of servodrift_fv include nothing of the valve"
