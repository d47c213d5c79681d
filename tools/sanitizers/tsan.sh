#!/usr/bin/env bash
# ThreadSanitizer over the threaded parts (the last stage of tools/sanitize.sh with CONFVIS_TSAN=1):
# builds confvis_threaded_tests (the threaded suites' files only, tests/CMakeLists.txt) and the CLI
# they run with clang-14 -fsanitize=thread into ./build-tsan and runs the suites that start threads:
#   the map follower and its background bake (MapFollower, BackgroundBake, BackgroundPriority),
#   the UDP trackers' receiver threads (UdpTracker, TrackerFactory, RecordedPath),
#   the bake's parallel cube faces and disk-map stages, the bake cache (Bake*, DisplayMap),
#   the Ricci flow's parallel assembly (RicciFlow, EveryScheme),
#   `confvis walk` (re-bakes behind the frames) and `confvis view` (the live window) end to end:
#   the CLI is built with TSan too and inherits TSAN_OPTIONS (CliWalk, CliView).
#   bash tools/sanitizers/tsan.sh [GTEST_FILTER]
# Any report fails the run (halt_on_error, tools/sanitizers/env.sh).
set -euo pipefail
cd "$(dirname "$0")/../.."
filter="${1:-MapFollower*:BackgroundBake*:BackgroundPriority*:UdpTracker*:TrackerFactory*:RecordedPath*:Bake.*:BakeCache*:BakePipeline*:DisplayMap.*:RicciFlow*:EveryScheme*:CliWalk*:CliView*}"
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S . -B build-tsan -G Ninja -DCMAKE_BUILD_TYPE=Sanitize -DCMAKE_CXX_COMPILER=clang++-14 \
  "-DCMAKE_CXX_FLAGS=-O1 -gline-tables-only -fno-omit-frame-pointer -fsanitize=thread" \
  -DCONFVIS_WERROR=OFF "${launcher[@]}" >/dev/null
cmake --build build-tsan -j"$(nproc)" --target confvis_threaded_tests
source tools/sanitizers/env.sh
./build-tsan/confvis_threaded_tests --gtest_filter="${filter}"
