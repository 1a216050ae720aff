#!/usr/bin/env bash
# fuzz.sh [SECONDS]: builds the libFuzzer harness over the program's readers
# (test/fuzz/fuzz_input.cpp) with clang, ASan and UBSan, replays the committed
# corpus, then fuzzes for SECONDS (default 60) with a fixed seed. New inputs
# go to build-fuzz/corpus, findings to build-fuzz/finding-*; any finding fails.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=Release -DENTROPY_SIMPLIFICATION_BUILD_TESTS=ON \
  -DENTROPY_SIMPLIFICATION_FUZZ=ON -DENTROPY_SIMPLIFICATION_BUILD_EXAMPLES=OFF -DENTROPY_SIMPLIFICATION_BUILD_DOC=OFF \
  > build-fuzz.log
cmake --build build-fuzz --target fuzz_input -j"$(nproc)" >> build-fuzz.log
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
mkdir -p build-fuzz/corpus
build-fuzz/test/fuzz/fuzz_input -runs=0 -artifact_prefix=build-fuzz/finding- test/fuzz/corpus
build-fuzz/test/fuzz/fuzz_input -seed=1 -max_total_time="$seconds" -max_len=8192 -timeout=20 -rss_limit_mb=4096 \
  -print_final_stats=1 -artifact_prefix=build-fuzz/finding- build-fuzz/corpus test/fuzz/corpus
echo "fuzzing: 0 findings in ${seconds} s"
