#!/usr/bin/env bash
# Before/after timing of the flow solver (issue 27: "no slower"): runs the same flow workloads with two
# builds in turn, A B A B ..., so that the machine's drift hits both alike, and prints the median wall
# time of each and the median of the pairwise ratios A/B. Not a test.
#   bench/compare_flow.sh BUILD_A BUILD_B [runs, default 5]
# BUILD_A, BUILD_B: build directories (or copies of them) with servodrift and bench/bench_flow,
# bench/bench_pilot_field. Workloads, one core each (OMP_THREAD_LIMIT=1):
#   pipe      bench_flow 1 20 0: the laminar pipe on 5 and 20 thousand cells to 1e-8
#   null      bench_pilot_field 1: RV-1's nozzle at its null, k-epsilon and laminar, resolution 1
#   sweep     servodrift flow tests/regression/pilot_field_default.prm: 16 field cases, resolution 0.5
set -eu
a=$(realpath "$1") b=$(realpath "$2") runs=${3:-5}
here=$(cd "$(dirname "$0")/.." && pwd)
export OMP_THREAD_LIMIT=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

seconds() { # wall seconds of one command
  local start end
  start=$(date +%s.%N)
  "$@" > /dev/null 2>&1
  end=$(date +%s.%N)
  echo "$end - $start" | bc -l
}
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

workload() { # NAME BUILD
  case $1 in
    pipe) echo "$2/bench/bench_flow 1 20 0" ;;
    null) echo "$2/bench/bench_pilot_field 1" ;;
    sweep) echo "$2/servodrift flow $here/tests/regression/pilot_field_default.prm -o $work/out" ;;
  esac
}

printf '%-6s %10s %10s %10s   (median of %d runs each, ratio = median of pairwise A/B)\n' workload "A [s]" "B [s]" "A/B" "$runs"
for name in pipe null sweep; do
  : > "$work/a" ; : > "$work/b" ; : > "$work/r"
  for _ in $(seq "$runs"); do
    ta=$(seconds $(workload $name "$a"))
    tb=$(seconds $(workload $name "$b"))
    echo "$ta" >> "$work/a"; echo "$tb" >> "$work/b"; echo "$ta / $tb" | bc -l >> "$work/r"
  done
  printf '%-6s %10.3f %10.3f %10.4f\n' $name "$(median < "$work/a")" "$(median < "$work/b")" "$(median < "$work/r")"
done
