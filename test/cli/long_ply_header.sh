#!/usr/bin/env bash
# long_ply_header.sh PROGRAM WORK: PLY headers of 1,000,000 element lines and
# of 300,000 vertex properties are read, and the files simplified, within
# the test's timeout: each line's check against the names before it once
# took time quadratic in their number (hours for these headers).
set -u
program=$1 work=$2
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; cat "$work/stderr.log"; exit 1; }
vertices() { for i in $(seq 0 19); do echo "$i $((i * i % 7)) $((i % 5))$1"; done; }

{
  printf 'ply\nformat ascii 1.0\n'
  seq 1 1000000 | sed 's/^/element e/; s/$/ 0/'
  printf 'element vertex 20\nproperty float x\nproperty float y\nproperty float z\nend_header\n'
  vertices ""
} > "$work/elements.ply"
"$program" "$work/elements.ply" "$work/elements_out.xyz" --count 12 -k 5 --quiet 2> "$work/stderr.log" ||
  fail "1,000,000 elements: exit code $?"
[ "$(wc -l < "$work/elements_out.xyz")" -eq 12 ] || fail "1,000,000 elements: not 12 points written"

{
  printf 'ply\nformat ascii 1.0\nelement vertex 20\nproperty float x\nproperty float y\nproperty float z\n'
  seq 1 300000 | sed 's/^/property uchar p/'
  printf 'end_header\n'
  vertices "$(printf ' 1%.0s' $(seq 1 300000))"
} > "$work/properties.ply"
"$program" "$work/properties.ply" "$work/properties_out.ply" --count 12 -k 5 --quiet 2> "$work/stderr.log" ||
  fail "300,000 properties: exit code $?"
grep -aq "^property uchar p300000$" "$work/properties_out.ply" || fail "300,000 properties: the last one not written"
echo "PLY headers of 1,000,000 elements and of 300,000 properties: read and simplified"
