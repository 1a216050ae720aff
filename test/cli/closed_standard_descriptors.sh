#!/usr/bin/env bash
# closed_standard_descriptors.sh PROGRAM INPUT WORK: started with its standard
# error closed (`2>&-`), or all three standard descriptors, the run writes the
# same output as with them open: the files it opens do not take their
# numbers, so the note it prints on stderr (the XYZ output drops the colours)
# does not go into the output.
set -u
program=$1 input=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
"$program" "$input" "$work/reference.xyz" --ratio 0.2 2> /dev/null || exit 1
for closed in stderr all; do
  rm -f "$work/out.xyz"
  if [ $closed = stderr ]; then
    "$program" "$input" "$work/out.xyz" --ratio 0.2 > /dev/null 2>&-
  else
    "$program" "$input" "$work/out.xyz" --ratio 0.2 <&- >&- 2>&-
  fi
  code=$?
  [ "$code" -eq 0 ] || { echo "FAIL: exit code $code, $closed closed"; ls -la "$work"; exit 1; }
  cmp "$work/out.xyz" "$work/reference.xyz" || { echo "FAIL: $closed closed, the output differs"; exit 1; }
  [ "$(ls -A "$work" | wc -l)" -eq 2 ] || { echo "FAIL: a temporary file was left"; ls -la "$work"; exit 1; }
done
echo "stderr closed, or all three standard descriptors: exit 0, the same output"
