#!/usr/bin/env bash
# ignored_hangup.sh PROGRAM INPUT WORK: a run started with SIGHUP ignored, as
# `nohup` starts it, survives a hangup (a closed terminal) and writes the
# same output as a run that received none.
set -u
program=$1 input=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
"$program" "$input" "$work/reference.ply" --ratio 0.01 --mode paper -k 20 --quiet || exit 1
trap '' HUP # what nohup does before it starts the program
"$program" "$input" "$work/out.ply" --ratio 0.01 --mode paper -k 20 --quiet &
pid=$!
trap - HUP
for _ in $(seq 400); do
  compgen -G "$work/.out.ply.??????" > /dev/null && break # the run is under way
  sleep 0.05
done
kill -HUP "$pid"
wait "$pid"
code=$?
[ "$code" -eq 0 ] || { echo "FAIL: exit code $code after an ignored SIGHUP"; ls -la "$work"; exit 1; }
cmp "$work/out.ply" "$work/reference.ply" || { echo "FAIL: the output differs from a run without SIGHUP"; exit 1; }
echo "SIGHUP ignored from the start: exit 0, the same output"
