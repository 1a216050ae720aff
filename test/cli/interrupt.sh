#!/usr/bin/env bash
# interrupt.sh PROGRAM INPUT WORK SIGNAL PHASE: sends SIGNAL (INT, TERM, HUP,
# QUIT, BUS, SEGV or KILL) to a run over an existing output, while it computes or, PHASE
# "writing", once it has written its result to the temporary file but not yet
# renamed it (a stuck disk, through the seam ENTROPY_SIMPLIFY_TEST_STALL_AFTER_BYTES).
# The existing output must be untouched. INT, TERM, HUP and QUIT exit with 130, BUS
# (what an input that shrinks while mapped raises) with 1, SEGV (a crash) with
# 139, each leaving no temporary file; after KILL, at most one hidden
# temporary file remains. With a sixth argument "all", the run also writes
# --indices and --render over existing files, which must be untouched too,
# their temporary files removed with the output's.
set -u
# job control: without it, the shell starts background jobs with SIGINT and
# SIGQUIT ignored, and the program keeps a signal ignored from the start
set -m
program=$1 input=$2 work=$3 signal=$4 phase=$5 outputs=${6:-}
rm -rf "$work" && mkdir -p "$work"
echo "an existing output" > "$work/out.ply"
echo "existing indices" > "$work/idx.txt"
echo "an existing picture" > "$work/view.png"
before=$(cat "$work/out.ply" "$work/idx.txt" "$work/view.png" | sha256sum)
if [ "$phase" = writing ]; then export ENTROPY_SIMPLIFY_TEST_STALL_AFTER_BYTES=1; fi
others=()
[ "$outputs" = all ] && others=(--indices "$work/idx.txt" --render "$work/view.png")
"$program" "$input" "$work/out.ply" --ratio 0.01 --mode paper -k 20 --quiet "${others[@]}" &
pid=$!
temporary() { compgen -G "$work/.out.ply.??????"; }
all_temporaries() { compgen -G "$work/.*.??????"; }
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
[ "$(cat "$work/out.ply" "$work/idx.txt" "$work/view.png" | sha256sum)" = "$before" ] || fail "an existing output was changed"
temporaries=$(all_temporaries | wc -l)
case $signal in
  KILL) expected=137 ;;    # killed: nothing can run
  BUS) expected=1 ;;       # the mapped input failed: a failure, reported
  SEGV) expected=139 ;;    # a crash stays a crash, without its temporary file
  *) expected=130 ;;       # INT, TERM, HUP, QUIT: interrupted
esac
[ "$code" -eq "$expected" ] || fail "exit code $code, expected $expected"
if [ "$signal" = KILL ]; then
  [ "$temporaries" -le 3 ] || fail "$temporaries temporary files left"
else
  [ "$temporaries" -eq 0 ] || fail "a temporary file was left"
fi
echo "SIG$signal while $phase: exit $code, output untouched, $temporaries temporary file(s)"
