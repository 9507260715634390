#!/usr/bin/env bash
# Regenerates the reference outputs of the regression cases (cases.txt). Run only when a change of
# the numbers is intended, and say why in the commit message:
#   tests/regression/regenerate.sh build/servodrift [CASE...]
# The environment is the tests' (CMakeLists.txt): one OpenMP thread, OpenBLAS's Haswell kernels.
set -eu
servodrift=$(realpath "$1")
shift
cd "$(dirname "$0")"
export OMP_THREAD_LIMIT=1 OPENBLAS_CORETYPE=Haswell
grep -v '^#' cases.txt | while read -r case command outputs; do
  [ $# -gt 0 ] && [[ " $* " != *" $case "* ]] && continue
  work=$(mktemp -d)
  "$servodrift" "$command" "$case.prm" -o "$work" > /dev/null
  mkdir -p "$case"
  for f in $outputs; do
    cp "$work/$f" "$case/$(basename "$f")"
  done
  rm -rf "$work"
  echo "regenerated $case"
done
