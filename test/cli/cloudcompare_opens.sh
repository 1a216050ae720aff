#!/usr/bin/env bash
# cloudcompare_opens.sh PROGRAM INPUT WORK FORMAT: CloudCompare, headless,
# opens the program's FORMAT output and saves the cloud it read, which must
# hold every point written.
set -eu
program=$1 input=$2 work=$3 format=$4
rm -rf "$work" && mkdir -p "$work"
"$program" "$input" "$work/out.$format" --count 300 --quiet
# CloudCompare writes its own log to stdout; the saved ASCII cloud is the proof
xvfb-run -a CloudCompare -SILENT -NO_TIMESTAMP -O "$work/out.$format" -C_EXPORT_FMT ASC -SAVE_CLOUDS \
  > "$work/cloudcompare.log" 2>&1 || true
saved=$(ls "$work"/out*.asc 2> /dev/null | head -1)
[ -n "$saved" ] || { echo "FAIL: CloudCompare did not open out.$format"; cat "$work/cloudcompare.log"; exit 1; }
lines=$(grep -cv '^//' "$saved")
[ "$lines" -eq 300 ] || { echo "FAIL: CloudCompare read $lines points of 300"; exit 1; }
echo "CloudCompare opened out.$format: 300 points"
