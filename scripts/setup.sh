#!/usr/bin/env bash
# Command 1: installs what is missing, builds the plugin, installs it so that plain `yade`
# loads it, and runs the main job: the papers' pair-collision figures (docs/figures.md) -> results/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build
cmake --build build -j"$(nproc)"
cmake --install build
yade -n -x scripts/figure.py --all --no-tablet --out results
