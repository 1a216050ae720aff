#!/usr/bin/env bash
# interrupt.sh PROGRAM INPUT WORK SIGNAL PHASE: sends SIGNAL (INT, TERM, HUP or
# KILL) to a run over an existing output, while it computes or, PHASE
# "writing", once it has written its result to the temporary file but not yet
# renamed it (a stuck disk, through the seam ENTROPY_SIMPLIFY_TEST_STALL_AFTER_BYTES).
# The existing output must be untouched; for INT, TERM and HUP, the run exits with
# 130 and leaves no temporary file; for KILL, at most one hidden temporary
# file remains.
set -u
program=$1 input=$2 work=$3 signal=$4 phase=$5
rm -rf "$work" && mkdir -p "$work"
echo "an existing output" > "$work/out.ply"
before=$(sha256sum < "$work/out.ply")
if [ "$phase" = writing ]; then export ENTROPY_SIMPLIFY_TEST_STALL_AFTER_BYTES=1; fi
"$program" "$input" "$work/out.ply" --ratio 0.01 --mode paper -k 20 --quiet &
pid=$!
temporary() { compgen -G "$work/.out.ply.??????"; }
for _ in $(seq 400); do
  if [ "$phase" = writing ]; then
    [ -s "$(temporary | head -1)" ] && break # bytes written: the run is in the writer
  else
    temporary > /dev/null && break # the run is under way
  fi
  sleep 0.05
done
[ "$phase" = writing ] || sleep 0.3
kill -"$signal" "$pid"
wait "$pid"
code=$?
fail() { echo "FAIL: $*"; ls -la "$work"; exit 1; }
[ "$(sha256sum < "$work/out.ply")" = "$before" ] || fail "the existing output was changed"
temporaries=$(temporary | wc -l)
if [ "$signal" = KILL ]; then
  [ "$code" -eq 137 ] || fail "exit code $code, expected 137 (killed)"
  [ "$temporaries" -le 1 ] || fail "$temporaries temporary files left"
else
  [ "$code" -eq 130 ] || fail "exit code $code, expected 130"
  [ "$temporaries" -eq 0 ] || fail "a temporary file was left"
fi
echo "SIG$signal while $phase: exit $code, output untouched, $temporaries temporary file(s)"
