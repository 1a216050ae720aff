#!/usr/bin/env bash
# file_size_limit.sh PROGRAM INPUT WORK: under a file size limit smaller than
# the output (`ulimit -f`), the run is not killed by SIGXFSZ with its
# temporary file left behind: it fails with "File too large", removes the
# temporary file and leaves the existing output untouched.
set -u
program=$1 input=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
echo "an existing output" > "$work/out.ply"
(ulimit -f 4 && "$program" "$input" "$work/out.ply" --ratio 0.9 --quiet) 2> "$work/stderr"
code=$?
fail() { echo "FAIL: $*"; cat "$work/stderr"; ls -la "$work"; exit 1; }
[ "$code" -eq 1 ] || fail "exit code $code, expected 1"
grep -q "cannot write '.*out.ply': File too large" "$work/stderr" || fail "no 'File too large' error"
[ "$(cat "$work/out.ply")" = "an existing output" ] || fail "the existing output was changed"
[ "$(ls -A "$work" | wc -l)" -eq 2 ] || fail "a temporary file was left"
echo "a file size limit: exit 1, File too large, the existing output untouched"
