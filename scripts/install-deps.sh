#!/usr/bin/env bash
# Installs the Debian packages the plugin needs: YADE itself and what compiling against its
# headers requires. Idempotent: does nothing when everything is present (no network then).
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive

packages=(yade cmake g++ make pkg-config binutils bzip2 xz-utils
          libeigen3-dev libboost-python1.74-dev libboost-serialization1.74-dev
          libboost-system1.74-dev libboost-log1.74-dev libboost-iostreams1.74-dev
          libopenmpi-dev python3-dev libbz2-dev libgtest-dev
          python3-numpy python3-scipy python3-matplotlib flake8 clang-format)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all packages present"
  exit 0
fi
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
echo "install-deps: installing ${missing[*]}"
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
