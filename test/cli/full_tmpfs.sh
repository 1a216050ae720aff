#!/usr/bin/env bash
# full_tmpfs.sh PROGRAM INPUT WORK: a real full disk, a 64 KiB tmpfs, holding
# an existing output: the run fails with the reason, and the existing output
# and the free space are as before. Skipped (exit 77) where tmpfs cannot be
# mounted (not root, or in a container that forbids it).
set -u
program=$1 input=$2 work=$3
mkdir -p "$work/disk"
mount -t tmpfs -o size=64k tmpfs "$work/disk" 2> /dev/null || { echo "cannot mount a tmpfs here: skipped"; exit 77; }
trap 'umount "$work/disk"' EXIT
echo "an existing output" > "$work/disk/out.ply"
"$program" "$input" "$work/disk/out.ply" --ratio 0.5 2> "$work/stderr.log"
code=$?
fail() { echo "FAIL: $*"; ls -la "$work/disk"; cat "$work/stderr.log"; exit 1; }
[ "$code" -eq 1 ] || fail "exit code $code, expected 1"
grep -q "cannot write '.*out.ply': No space left on device" "$work/stderr.log" || fail "no reason given"
[ "$(cat "$work/disk/out.ply")" = "an existing output" ] || fail "the existing output was changed"
[ "$(ls -A "$work/disk" | wc -l)" -eq 1 ] || fail "a temporary file was left"
echo "a full tmpfs: exit 1, the reason given, the existing output untouched, nothing left"
