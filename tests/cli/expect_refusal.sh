#!/usr/bin/env bash
# Bad input must give: a non-zero exit code (not a crash), exactly one line on stderr naming what to
# fix (containing EXPECTED), and no output file left behind.
# usage: expect_refusal.sh SERVODRIFT EXPECTED SETUP -- ARGS...   (SETUP: a shell snippet run in $work)
set -u
servodrift=$1 expected=$2 setup=$3
shift 4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
eval "$setup"
before=$(find . -type f | sort)
"$servodrift" "$@" > stdout.txt 2> stderr.txt
code=$?
after=$(find . -type f ! -name stdout.txt ! -name stderr.txt | sort)
fail() { echo "FAIL: $*"; echo "--- stderr:"; cat stderr.txt; exit 1; }
[ "$code" -ne 0 ] || fail "exit code 0"
[ "$code" -lt 128 ] || fail "crashed with exit code $code"
[ "$(wc -l < stderr.txt)" -eq 1 ] || fail "stderr is not exactly one line"
grep -qF -- "$expected" stderr.txt || fail "stderr does not contain: $expected"
[ "$before" = "$after" ] || fail "output files were left behind: $(comm -13 <(echo "$before") <(echo "$after") | tr '\n' ' ')"
! grep -rqiE '(^|,)-?nan(,|$)' . --include='*.csv' || fail "NaN in a CSV file"
echo "ok: exit $code: $(cat stderr.txt)"
