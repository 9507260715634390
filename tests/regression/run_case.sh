#!/usr/bin/env bash
# Runs one regression case of cases.txt and compares its text outputs with the references
# (compare_csv). Not compared in flow/*_cases.csv: the wall time, and the largest residual of the
# state a case stopped at (below the tolerance where it converged: round-off changes it by more
# than the comparison's 1e-6 while it changes nothing else).
#   run_case.sh SERVODRIFT COMPARE_CSV CASE
set -eu
servodrift=$1 compare=$2 case=$3
here=$(dirname "$0")
read -r _ command outputs < <(grep "^$case " "$here/cases.txt")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$servodrift" "$command" "$here/$case.prm" -o "$work" > /dev/null
status=0
for f in $outputs; do
  echo -n "$f: "
  ignore=()
  grep -q "wall_time\[s\]" "$here/$case/$(basename "$f")" && ignore=(--ignore "wall_time[s]" --ignore "largest_residual[1]")
  "$compare" "${ignore[@]}" "$here/$case/$(basename "$f")" "$work/$f" || status=1
done
exit $status
