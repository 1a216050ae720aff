#!/usr/bin/env bash
# closed_stderr.sh PROGRAM INPUT WORK: with its standard error a pipe closed
# by the reader (`| true`, `| head -1`), the run is not killed by SIGPIPE
# halfway, leaving a temporary file: it finishes and writes its output.
set -u
program=$1 input=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
# the XYZ output drops the colours, which prints a note to the closed pipe
"$program" "$input" "$work/out.xyz" --ratio 0.5 2>&1 >/dev/null | true
code=${PIPESTATUS[0]}
[ "$code" -eq 0 ] || { echo "FAIL: exit code $code"; ls -la "$work"; exit 1; }
[ -s "$work/out.xyz" ] || { echo "FAIL: no output"; exit 1; }
[ "$(ls -A "$work" | wc -l)" -eq 1 ] || { echo "FAIL: a temporary file was left"; ls -la "$work"; exit 1; }
echo "a closed stderr: exit 0, the output written, nothing left"
