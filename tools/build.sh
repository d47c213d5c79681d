#!/usr/bin/env bash
# Installs dependencies (Debian packages) and builds confvis into ./build (Release).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
# ccache, where a developer installed it, shares objects between checkouts; CI has none.
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
# The test binaries' own files -O1 (the libraries, the CLI and the tools stay Release, -O3): a
# fifth to a third less compile time for the largest part of the build.
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCONFVIS_WERROR=ON \
  -DCONFVIS_TEST_COMPILE_OPTIONS=-O1 "${launcher[@]}" >/dev/null
cmake --build build -j"$(nproc)"
