#!/usr/bin/env bash
# Builds and runs the test suite (Catch2 through CTest), including the
# documentation build, the command-line tool and an install + find_package check.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DENTROPY_SIMPLIFICATION_BUILD_TESTS=ON
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)"
