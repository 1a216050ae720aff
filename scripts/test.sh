#!/usr/bin/env bash
# Builds and runs the test suite (Catch2 and the command-line tests through
# CTest), including the documentation build and an install + find_package
# check; then the Catch2 test cases again under AddressSanitizer and UBSan; then
# the fuzzer: the committed corpus replayed, and 60 s of fuzzing with a fixed
# seed, under ASan and UBSan (see test/fuzz/).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DENTROPY_SIMPLIFICATION_BUILD_TESTS=ON
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)"

cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Release -DENTROPY_SIMPLIFICATION_BUILD_TESTS=ON \
  -DENTROPY_SIMPLIFICATION_SANITIZE=ON -DENTROPY_SIMPLIFICATION_BUILD_EXAMPLES=OFF -DENTROPY_SIMPLIFICATION_BUILD_DOC=OFF
cmake --build build-asan --target entropy_simplification_tests entropy_simplify_program_tests -j"$(nproc)"
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
# one process per test case (label catch2), as many at once as there are cores
ctest --test-dir build-asan -L catch2 --output-on-failure -j"$(nproc)"

bash scripts/fuzz.sh 60
