#!/usr/bin/env bash
# full_stdout.sh PROGRAM INPUT WORK: with the standard output a full device
# (/dev/full), a run asked for a report, and one asked for the help, fail
# with the reason instead of exiting 0 with the text lost; the run's output
# file, written before the report, is in place and the message says so.
set -u
program=$1 input=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; cat "$work/stderr.log"; exit 1; }

"$program" "$input" "$work/out.xyz" --ratio 0.5 --report > /dev/full 2> "$work/stderr.log"
code=$?
[ "$code" -eq 1 ] || fail "a report to a full stdout: exit code $code, expected 1"
grep -q "^entropy_simplify: cannot write to the standard output: No space left on device; .*out.xyz is written$" \
  "$work/stderr.log" || fail "a report to a full stdout: no reason given"
[ -s "$work/out.xyz" ] || fail "the output was not written"

"$program" --help > /dev/full 2> "$work/stderr.log"
code=$?
[ "$code" -eq 1 ] || fail "the help to a full stdout: exit code $code, expected 1"
grep -q "^entropy_simplify: cannot write to the standard output: No space left on device$" "$work/stderr.log" ||
  fail "the help to a full stdout: no reason given"

# quiet and without a report, nothing is printed, so nothing can be lost
"$program" "$input" "$work/quiet.xyz" --ratio 0.5 --quiet > /dev/full 2> "$work/stderr.log" ||
  fail "a quiet run with a full stdout failed"
echo "a full stdout: exit 1 and the reason, for a report and for the help; a quiet run is not affected"
