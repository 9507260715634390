#!/usr/bin/env bash
# Benchmark: wall time of the README's main job, `servodrift run' on the built-in valve RV-1, with
# plots and report, serial and on 2 MPI ranks. Issue 2's target (under 10 s on this 2-core machine)
# is for every stage at the reduced-order level (--set "<stage>/Model level=reduced-order" for the
# torque motor, spring tube and pilot stage); with the defaults (every stage at the field level) one
# run takes about 5.5 min on 2 ranks (doc/performance.md).
#   bench/run_servodrift.sh [build-dir] [repetitions] [servodrift options...]
set -eu
build=${1:-build} n=${2:-5}
shift 2 || true
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
measure() {
  local times=()
  for _ in $(seq "$n"); do
    local s e
    s=$(date +%s%N); "$@" > /dev/null 2>&1; e=$(date +%s%N)
    times+=("$(( (e - s) / 1000000 ))")
  done
  printf '%s\n' "${times[@]}" | sort -g | awk '{a[NR]=$1/1000} END {printf "min %.3f s, median %.3f s (%d runs)\n", a[1], a[int((NR+1)/2)], NR}'
}
echo -n "servodrift run (1 rank):            "; measure "$build/servodrift" run -o "$out/a" "$@"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
echo -n "mpirun -np 2 servodrift run:        "; measure mpirun -np 2 "$build/servodrift" run -o "$out/b" "$@"
