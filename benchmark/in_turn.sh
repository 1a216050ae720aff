#!/usr/bin/env bash
# Times this commit's default mode in turn against an earlier commit's, by
# default 3bd26f7 (issue 7's last run, with weighted sample elimination,
# whose figures bound issue 12's speed), on the benchmark's replicas, the
# lion and 1,000,000 lion samples, kept to 10%: each build runs RUNS times in
# one process, the two builds alternately, in PROCESSES rounds, and the
# script prints each build's median, the ratio of the medians, and whether
# the two kept the same points. Seconds from separate runs of a shared
# machine do not compare; ratios within one set of runs in turn do, to a few
# hundredths. Needs run.sh's data (build-benchmark/cgal_data), or DATA.
#
# usage: benchmark/in_turn.sh [COMMIT [THREADS [RUNS [PROCESSES]]]]
set -euo pipefail
cd "$(dirname "$0")/.."
base="${1:-3bd26f7}"
threads="${2:-2}"
runs="${3:-3}"
processes="${4:-2}"
data="${DATA:-build-benchmark/cgal_data/data}"
[ -f "$data/meshes/lion.off" ] || {
  echo "benchmark/in_turn.sh: no $data/meshes/lion.off (run benchmark/run.sh --quick once, or set DATA)" >&2
  exit 1
}
work=build-benchmark/in_turn
rm -rf "$work"
mkdir -p "$work/base"
git archive "$base" include | tar -x -C "$work/base"
flags=(-std=c++17 -O3 -DNDEBUG -DCGAL_LINKED_WITH_TBB -DCGAL_EIGEN3_ENABLED -I/usr/include/eigen3 -Ibenchmark)
libraries=(-ltbb -lgmp -lmpfr)
g++ "${flags[@]}" -I"$work/base/include" benchmark/bench_in_turn.cpp -o "$work/base_build" "${libraries[@]}" &
base_compiler=$!
g++ "${flags[@]}" -Iinclude benchmark/bench_in_turn.cpp -o "$work/this_build" "${libraries[@]}"
wait "$base_compiler"

median() { sort -n | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

echo "input, ${base} (s), this commit (s), ratio, same points; ${threads} threads, ${runs} runs x ${processes} processes each"
for input in replica_2mm replica_1.2mm lion lion_1M; do
  for ((p = 0; p < processes; ++p)); do
    for build in base this; do
      "$work/${build}_build" "$data" "$input" 10 "$runs" "$threads" >>"$work/${build}.${input}"
    done
  done
  b=$(cut -d' ' -f1 "$work/base.${input}" | median)
  t=$(cut -d' ' -f1 "$work/this.${input}" | median)
  same=no
  if [ "$(cut -d' ' -f2 "$work/base.${input}" | sort -u)" = "$(cut -d' ' -f2 "$work/this.${input}" | sort -u)" ]; then
    same=yes
  fi
  awk -v i="$input" -v b="$b" -v t="$t" -v s="$same" 'BEGIN { printf "%s, %.3f, %.3f, %.3f, %s\n", i, b, t, t / b, s }'
done
