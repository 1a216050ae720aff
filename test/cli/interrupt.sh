#!/usr/bin/env bash
# interrupt.sh PROGRAM INPUT WORK SIGNAL: sends SIGNAL (INT, TERM or KILL) to
# a run over an existing output, and checks that the output is untouched;
# for INT and TERM, that the run exits with 130 and leaves no temporary file,
# for KILL, that at most one hidden temporary file remains.
set -u
program=$1 input=$2 work=$3 signal=$4
rm -rf "$work" && mkdir -p "$work"
echo "an existing output" > "$work/out.ply"
before=$(sha256sum < "$work/out.ply")
"$program" "$input" "$work/out.ply" --ratio 0.01 --mode paper -k 20 --quiet &
pid=$!
# signal once the run is under way: its temporary file exists
for _ in $(seq 100); do
  compgen -G "$work/.out.ply.??????" > /dev/null && break
  sleep 0.05
done
sleep 0.3
kill -"$signal" "$pid"
wait "$pid"
code=$?
fail() { echo "FAIL: $*"; ls -la "$work"; exit 1; }
[ "$(sha256sum < "$work/out.ply")" = "$before" ] || fail "the existing output was changed"
temporaries=$(compgen -G "$work/.out.ply.??????" | wc -l)
if [ "$signal" = KILL ]; then
  [ "$code" -eq 137 ] || fail "exit code $code, expected 137 (killed)"
  [ "$temporaries" -le 1 ] || fail "$temporaries temporary files left"
else
  [ "$code" -eq 130 ] || fail "exit code $code, expected 130"
  [ "$temporaries" -eq 0 ] || fail "a temporary file was left"
fi
echo "SIG$signal: exit $code, output untouched, $temporaries temporary file(s)"
