#!/usr/bin/env bash
# The benchmark's one command. Builds it (-O3 -DNDEBUG), runs every method on
# every input, writes benchmark/RESULTS.md and benchmark/results/ (CSV, data,
# figures), then the sections "Coincident points" (bench_duplicates),
# "Scale" (bench_scale, 100k to 10M points, about 7 to 15 minutes), "Levels of
# detail" (bench_lod, about 3 minutes), "What each term contributes"
# (bench_ablation, about 4 minutes), "Point-to-plane error and noise"
# (bench_noise, about 5 minutes) and "Thin walls" (bench_thin_walls, about
# 20 seconds) of RESULTS.md. With --quick: smaller
# inputs, a couple of minutes,
# written to build-benchmark/quick/ so that the committed results stay as they
# are.
set -euo pipefail
cd "$(dirname "$0")/.."
mode="${1:-}"
if [ -n "$mode" ] && [ "$mode" != "--quick" ]; then
  echo "usage: benchmark/run.sh [--quick]" >&2
  exit 2
fi
out=benchmark
if [ "$mode" = "--quick" ]; then out=build-benchmark/quick; fi
command -v gnuplot >/dev/null || { echo "benchmark/run.sh: gnuplot is missing (apt-get install gnuplot-nox)" >&2; exit 1; }

cmake -S . -B build-benchmark -DCMAKE_BUILD_TYPE=Release -DENTROPY_SIMPLIFICATION_BUILD_BENCHMARKS=ON \
  -DENTROPY_SIMPLIFICATION_BUILD_EXAMPLES=ON -DENTROPY_SIMPLIFICATION_BUILD_DOC=OFF >/dev/null
cmake --build build-benchmark --target run_benchmark bench_quality_baseline bench_duplicates bench_scale bench_lod bench_ablation bench_noise bench_thin_walls entropy_simplify -j"$(nproc)"
mkdir -p "$out/results"
rm -f "$out"/results/*.png "$out"/results/points/*.txt
build-benchmark/benchmark/run_benchmark --data build-benchmark/cgal_data/data --out "$out" $mode
# Quality against the start of the speed work (issue 10), cell by cell; the
# quick run's smaller inputs have no baseline.
if [ -z "$mode" ]; then
  build-benchmark/benchmark/bench_quality_baseline --baseline benchmark/results/quality_baseline.csv \
    --current benchmark/results/quality.csv >> "$out/RESULTS.md"
fi
# Coincident points: one process per case, its section appended to RESULTS.md
# (--smoke with --quick: the smaller cases, without the 220k reference).
build-benchmark/benchmark/bench_duplicates ${mode:+--smoke} --append "$out/RESULTS.md"
# Scale: the inputs are written once to build-benchmark/scale (about 170 MB of
# lion samples up to 10M points); --quick stops at 300k points.
build-benchmark/benchmark/bench_scale --data build-benchmark/cgal_data/data --work build-benchmark/scale \
  --program build-benchmark/examples/entropy_simplify --out "$out" \
  ${mode:+--sizes 100000,300000 --runs 1}
# Levels of detail: printed as its section, the figures in results/lod.csv.
build-benchmark/benchmark/bench_lod --data build-benchmark/cgal_data/data --out "$out/results" ${mode:+--smoke} \
  >> "$out/RESULTS.md"
# The ablation of the default mode's terms, against the peers of this run.
build-benchmark/benchmark/bench_ablation --data build-benchmark/cgal_data/data --quality "$out/results/quality.csv" \
  --out "$out/results" ${mode:+--smoke} >> "$out/RESULTS.md"
# On the noisy inputs, the point-to-plane error against the noise the kept
# points carry (--smoke with --quick: small replicas, CGAL's peers only).
build-benchmark/benchmark/bench_noise --data build-benchmark/cgal_data/data --out "$out/results" ${mode:+--smoke} \
  >> "$out/RESULTS.md"
# The machined parts' point-to-plane error by the thickness of their walls
# (--smoke with --quick: a small sample of rotor).
build-benchmark/benchmark/bench_thin_walls --data build-benchmark/cgal_data/data --out "$out/results" ${mode:+--smoke} \
  >> "$out/RESULTS.md"
(cd "$out/results" && for script in *.gp; do gnuplot "$script"; done)
echo "benchmark/run.sh: wrote $out/RESULTS.md"
