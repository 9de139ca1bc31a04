#!/usr/bin/env bash
# Command 2: runs the test suite with ctest (builds first if needed; nothing is installed).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)"
