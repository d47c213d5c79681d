#!/usr/bin/env bash
# ThreadSanitizer over the threaded parts (the last stage of tools/sanitize.sh): builds with
# clang-14 -fsanitize=thread into ./build-tsan and runs the suites that start threads.
#   bash tools/sanitizers/tsan.sh [--full] [GTEST_FILTER]
# Default (CI): confvis_threaded_tests (tests/CMakeLists.txt), which compiles only base, engine,
# conformal and the runtime's threaded files (no backends, Vulkan or CLI):
#   the map follower and its background bake (MapFollower, BackgroundBake, BackgroundPriority),
#   the UDP trackers' receiver threads (UdpTracker, TrackerFactory, RecordedPath),
#   the bake's parallel cube faces and disk-map stages, the bake cache (Bake*, DisplayMap),
#   the Ricci flow's parallel assembly (RicciFlow, EveryScheme), and the regression tests of
#   races TSan found (*Race*).
# --full (by hand; it compiles the whole project with TSan, too long for CI): also
#   `confvis walk` (re-bakes behind the frames) and `confvis view` (the live window) end to end
#   (CliWalk, CliView): the CLI is built with TSan too and inherits TSAN_OPTIONS.
# The test files compile -O0 (~20 % less compile time for them; they only start threads and
# compare), the code under test -O1 as before. Any report fails the run (halt_on_error,
# tools/sanitizers/env.sh).
set -euo pipefail
cd "$(dirname "$0")/../.."
full=0
if [ "${1:-}" = --full ]; then full=1; shift; fi
filter="${1:-*}"
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S . -B build-tsan -G Ninja -DCMAKE_BUILD_TYPE=Sanitize -DCMAKE_CXX_COMPILER=clang++-14 \
  "-DCMAKE_CXX_FLAGS=-O1 -gline-tables-only -fno-omit-frame-pointer -fsanitize=thread" \
  -DCONFVIS_TEST_COMPILE_OPTIONS=-O0 -DCONFVIS_WERROR=OFF "${launcher[@]}" >/dev/null
targets=(confvis_threaded_tests)
if [ "${full}" = 1 ]; then targets+=(confvis_threaded_cli_tests); fi
cmake --build build-tsan -j"$(nproc)" --target "${targets[@]}"
source tools/sanitizers/env.sh
# Reports on stdout: a test that captures stderr (gtest's CaptureStderr) would swallow them.
export TSAN_OPTIONS="${TSAN_OPTIONS}:log_path=stdout"
./build-tsan/confvis_threaded_tests --gtest_filter="${filter}"
if [ "${full}" = 1 ]; then
  ./build-tsan/confvis_threaded_cli_tests --gtest_filter="${filter}"
fi
