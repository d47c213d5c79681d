#!/usr/bin/env bash
# Installs dependencies (Debian packages) and builds confvis into ./build (Release).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCONFVIS_WERROR=ON >/dev/null
cmake --build build -j"$(nproc)"
