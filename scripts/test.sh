#!/usr/bin/env bash
# Builds and runs the test suite (Catch2 through CTest), including the
# documentation build, the command-line tool and an install + find_package
# check; then the Catch2 suite again under AddressSanitizer and UBSan.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DENTROPY_SIMPLIFICATION_BUILD_TESTS=ON
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)"

cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Release -DENTROPY_SIMPLIFICATION_BUILD_TESTS=ON \
  -DENTROPY_SIMPLIFICATION_SANITIZE=ON -DENTROPY_SIMPLIFICATION_BUILD_EXAMPLES=OFF -DENTROPY_SIMPLIFICATION_BUILD_DOC=OFF
cmake --build build-asan --target entropy_simplification_tests -j"$(nproc)"
UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 build-asan/test/entropy_simplification_tests
