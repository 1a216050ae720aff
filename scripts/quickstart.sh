#!/usr/bin/env bash
# Sets everything up on a fresh Debian 12 machine and runs the main job on
# built-in data: the replica of the paper's Experiment I (182,191 points)
# simplified to 10% with each removal order.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
build/examples/experiment_I
