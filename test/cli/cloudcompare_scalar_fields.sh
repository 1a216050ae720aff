#!/usr/bin/env bash
# cloudcompare_scalar_fields.sh PROGRAM INPUT WORK: CloudCompare, headless,
# opens the PLY that --lod --importance writes with the scalar fields 'rank'
# and 'importance', and every point; the saved cloud lists them in its header.
set -eu
program=$1 input=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
"$program" "$input" "$work/lod.ply" --lod --ratio 0.1 --importance --quiet
points=$(grep -a -m1 '^element vertex' "$work/lod.ply" | cut -d' ' -f3)
xvfb-run -a CloudCompare -SILENT -NO_TIMESTAMP -O "$work/lod.ply" -C_EXPORT_FMT ASC -ADD_HEADER -SAVE_CLOUDS \
  > "$work/cloudcompare.log" 2>&1 || true
saved=$(ls "$work"/lod*.asc 2> /dev/null | head -1)
[ -n "$saved" ] || { echo "FAIL: CloudCompare did not open lod.ply"; cat "$work/cloudcompare.log"; exit 1; }
header=$(head -1 "$saved")
case "$header" in
  *" rank importance"*) ;;
  *) echo "FAIL: CloudCompare's scalar fields are '$header', not rank and importance"; exit 1 ;;
esac
lines=$(grep -cv '^//' "$saved")
[ "$lines" -eq "$points" ] || { echo "FAIL: CloudCompare read $lines points of $points"; exit 1; }
echo "CloudCompare opened lod.ply: $lines points, scalar fields rank and importance ($header)"
