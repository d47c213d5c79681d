#!/usr/bin/env bash
# Installs dependencies (Debian packages) and builds confvis into ./build (Release).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
# ccache, where a developer installed it, shares objects between checkouts; CI has none.
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCONFVIS_WERROR=ON "${launcher[@]}" >/dev/null
cmake --build build -j"$(nproc)"
