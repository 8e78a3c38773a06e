#!/usr/bin/env bash
# Installs the Debian packages springcheck needs (only those missing), then configures and
# builds one CMake preset. Usage: scripts/setup.sh [preset] [targets...]
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(cmake g++ make ninja-build pkg-config libbullet-dev libeigen3-dev googletest libgtest-dev
          libbenchmark-dev nlohmann-json3-dev libcli11-dev python3-matplotlib python3-numpy
          libglfw3-dev libgl-dev libgl1-mesa-dri xvfb xauth help2man
          libpng-dev libstb-dev fonts-dejavu-core xdotool nodejs)
scripts/install-packages.sh "${packages[@]}"

preset=${1:-default}
shift || true
cmake --preset "$preset" >/dev/null
if (($#)); then
  cmake --build --preset "$preset" -j "$(nproc)" --target "$@"
else
  cmake --build --preset "$preset" -j "$(nproc)"
fi
