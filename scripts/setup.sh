#!/usr/bin/env bash
# Command 1: installs what is missing, builds the plugin, packages it as a Debian package and
# installs that (so plain `yade` loads it and `apt remove yade-meso` takes every file away
# again), then runs the main job: the papers' pair-collision figures (docs/figures.md) -> results/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build
cmake --build build -j"$(nproc)"
(cd build && cpack -G DEB)
deb=$(ls build/yade-meso_*_amd64.deb)
SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
$SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --reinstall "./$deb"
# the installed plugin and library; the figures are a study, run from this checkout
PYTHONPATH=studies yade -n -x studies/scripts/figure.py --all --no-tablet --out results
