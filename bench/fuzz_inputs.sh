#!/usr/bin/env bash
# Long mode of the fuzz driver of bad input (tests/fuzz/fuzz_inputs.cc; ctest's cli.fuzz_inputs and
# cli.fuzz_surfaces run up to 30 runs of seeds 1 and 5): many runs of any seed, of every mutation
# kind or of those named (value,structure,json,command-line for `run', tolerances,dynamics,calibrate
# for the newer surfaces). Failures are kept, with a cmd.sh that replays each, under
# <work>/failures/; the seed is printed so that the same runs can be repeated (with the same kinds).
#   bench/fuzz_inputs.sh [build-dir] [runs] [seed] [work-dir] [timeout-s] [kinds]
# Build the driver first: cmake --build build --target fuzz_inputs
set -eu
build=${1:-build} runs=${2:-1000} seed=${3:-$(date +%s)} work=${4:-$(mktemp -d -t servodrift-fuzz.XXXXXX)} timeout=${5:-60}
kinds=${6:-value,structure,json,command-line,tolerances,dynamics,calibrate}
echo "fuzz_inputs: seed $seed, $runs runs of $kinds, work $work"
exec "$build/tests/fuzz/fuzz_inputs" --servodrift "$build/servodrift" --work "$work" --seed "$seed" \
  --runs "$runs" --timeout "$timeout" --kinds "$kinds"
