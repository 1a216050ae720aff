#!/usr/bin/env bash
# progress_bar.sh PROGRAM INPUT WORK: a run of over a second draws a progress
# bar on a terminal (script(1) gives it one), and none when stderr is a file.
set -eu
program=$1 input=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
script -qec "'$program' '$input' '$work/a.ply' --ratio 0.01 --mode paper -k 20" "$work/terminal.log" > /dev/null
grep -q '\] 100%' "$work/terminal.log" || { echo "FAIL: no progress bar on a terminal"; cat -v "$work/terminal.log"; exit 1; }
"$program" "$input" "$work/b.ply" --ratio 0.01 --mode paper -k 20 2> "$work/stderr.log" > /dev/null
if grep -q '%' "$work/stderr.log"; then echo "FAIL: a progress bar in a file"; cat -v "$work/stderr.log"; exit 1; fi
echo "a progress bar on a terminal, none in a file"
