#!/usr/bin/env bash
# Bad input must give: a non-zero exit code (not a crash), exactly one line on stderr naming what to
# fix (containing EXPECTED; printable ASCII, at most 400 characters), and the working directory as
# it was (no file or directory left behind, none changed: issue 24).
# usage: expect_refusal.sh SERVODRIFT EXPECTED SETUP -- ARGS...   (SETUP: a shell snippet run in $work)
set -u
servodrift=$1 expected=$2 setup=$3
shift 4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
eval "$setup"
snapshot() { find . ! -name stdout.txt ! -name stderr.txt ! -name . -printf '%y %p\n' | sort
             find . -type f ! -name stdout.txt ! -name stderr.txt -exec md5sum {} + | sort; }
before=$(snapshot)
"$servodrift" "$@" > stdout.txt 2> stderr.txt
code=$?
after=$(snapshot)
fail() { echo "FAIL: $*"; echo "--- stderr:"; cat stderr.txt; exit 1; }
[ "$code" -ne 0 ] || fail "exit code 0"
[ "$code" -lt 128 ] || fail "crashed with exit code $code"
[ "$(wc -l < stderr.txt)" -eq 1 ] || fail "stderr is not exactly one line"
grep -qF -- "$expected" stderr.txt || fail "stderr does not contain: $expected"
[ "$(wc -c < stderr.txt)" -le 401 ] || fail "stderr is longer than 400 characters"
! LC_ALL=C grep -q '[^[:print:]]' stderr.txt || fail "stderr holds non-printable characters"
[ "$before" = "$after" ] || fail "the directory changed: $(diff <(echo "$before") <(echo "$after") | grep '^[<>]' | head -5 | tr '\n' ' ')"
! grep -rqiE '(^|,)-?nan(,|$)' . --include='*.csv' || fail "NaN in a CSV file"
echo "ok: exit $code: $(cat stderr.txt)"
