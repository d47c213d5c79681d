#!/usr/bin/env bash
# The sanitizer stage of CI (run by tools/test.sh after the normal build and tests; opt out with
# CONFVIS_SANITIZE=0):
#   1. build-asan/: clang-14, AddressSanitizer + UndefinedBehaviorSanitizer (+ LeakSanitizer),
#      the libraries also with -fsanitize=fuzzer-no-link so the same build links the libFuzzer
#      harnesses of tests/fuzz (the test files -O0 without it); only what the stage runs is built
#      (the test binaries, the CLI they start, the harnesses; no benchmarks or example
#      applications), and the whole test suite runs there (but for the packaging tests in
#      $excluded), the Vulkan, window and MPI tests two at a time but for the live-view ones;
#   2. every fuzz harness for CONFVIS_FUZZ_SECONDS (default 10) from its seed corpus, one per
#      core side by side (tests/fuzz/run.sh; 0 skips it);
#   3. ThreadSanitizer over the library-level threaded suites (tools/sanitizers/tsan.sh, in
#      build-tsan/: base, engine, conformal and the runtime's threaded files only, ~320 CPU s
#      from clean, ~3 min on CI); CONFVIS_TSAN=0 skips it. The CLI-level suites (walk, view)
#      under TSan need the whole project built again: by hand, tsan.sh --full.
# Costs on CI and why the fuzz time is 10 s: tests/fuzz/README.md, "In CI".
# With CONFVIS_SANITIZE_SHARED=1, build-asan builds the confvis libraries shared
# (CONFVIS_SHARED_LIBS=ON: hidden visibility; the test binaries link the modules' objects, the CLI
# and the harnesses the libraries) at no extra compile cost, and the suite adds
# shared_libraries_export_only_the_public_api; off by default until such a run has been seen
# clean (switching an existing build-asan rebuilds every object: other visibility flags).
# Any sanitizer report, leak or fuzz finding fails the run (tools/sanitizers/env.sh). Each stage
# prints when it starts: wall seconds and CPU seconds (all processes it waited for) since the start.
set -euo pipefail
cd "$(dirname "$0")/.."
fuzz_seconds="${CONFVIS_FUZZ_SECONDS:-10}"
stage() {  # wall seconds since the start; CPU seconds of all finished child processes
  local cpu  # from /proc: `times` in a $(...) subshell would count that subshell's children
  cpu=$(awk -v hz="$(getconf CLK_TCK)" '{ printf "%.0f", ($16 + $17) / hz }' "/proc/$$/stat")
  echo "sanitize: $1 ($(date -u +%T), ${SECONDS} s since start, ${cpu} CPU s)"
}

# Left out: they test packaging with the system compiler (an installed package built into an
# outside project, confvis as a subproject, the symbols an AVX2 object exports), which the normal
# build already ran; with instrumented objects they would only test the instrumentation.
excluded='consumer_package|consumer_shared_package|subproject_with_makefiles|embree_avx2_object_exports_only_its_kernel'

flags="-O1 -gline-tables-only -fno-omit-frame-pointer -fsanitize=address,undefined"
flags+=" -fno-sanitize-recover=all -fsanitize=fuzzer-no-link"
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
stage "building build-asan"
# Build type "Sanitize": no preset flags of its own (so assertions stay on), all in $flags.
shared=OFF
if [ "${CONFVIS_SANITIZE_SHARED:-0}" != 0 ]; then shared=ON; fi
# The test binaries' own files (half the build's compile time): -O0, and no coverage
# instrumentation, which only the fuzz harnesses' libraries need; still under ASan and UBSan.
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Sanitize -DCMAKE_CXX_COMPILER=clang++-14 \
  "-DCMAKE_CXX_FLAGS=${flags}" -DCONFVIS_WERROR=OFF -DCONFVIS_FUZZ=ON \
  "-DCONFVIS_TEST_COMPILE_OPTIONS=-O0;-fno-sanitize=fuzzer-no-link" \
  -DCONFVIS_SHARED_LIBS=${shared} "${launcher[@]}" >/dev/null
targets=(confvis_tests confvis)
if ninja -C build-asan -t query confvis_cluster_tests >/dev/null 2>&1; then
  targets+=(confvis_cluster_tests)
fi
cmake --build build-asan -j"$(nproc)" --target "${targets[@]}"

# Tests that load a Vulkan driver (lavapipe, its LLVM, the validation layer) or open an X11
# window (label vulkan_or_window, tests/label_native_tests.cmake) or start Open MPI (label mpi)
# run with ASan and UBSan but without LeakSanitizer: the Vulkan loader and Open MPI dlclose those
# modules before exit, so their leaks show as "<unknown module>" and no suppression can name
# them. Everything else runs with LeakSanitizer.
unattributable_leaks='vulkan_or_window|mpi'

# A clean build-asan has no test costs yet: the normal build's (build/, the same tests, all
# passed) let ctest start the longest first, so that none is left running alone at the end.
costs=Testing/Temporary/CTestCostData.txt
if [ -f "build/${costs}" ] && [ ! -f "build-asan/${costs}" ]; then
  mkdir -p build-asan/Testing/Temporary
  cp "build/${costs}" "build-asan/${costs}"
fi

source tools/sanitizers/env.sh
stage "the test suite under ASan + UBSan + LSan"
ctest --test-dir build-asan --output-on-failure -j"$(nproc)" -LE "${unattributable_leaks}" \
  -E "^(${excluded})\$"
# Two at a time but for the live-view suites, which count frames in a time window (CliViewLive,
# CliView: too few frames when two ran side by side under ASan on a loaded machine; they pass
# alone) and run one at a time afterwards; the MPI tests are RUN_SERIAL (tests/CMakeLists.txt).
frame_timed='CliView|CliViewLive'
stage "the Vulkan, window and MPI tests under ASan + UBSan"
ASAN_OPTIONS="${ASAN_OPTIONS/detect_leaks=1/detect_leaks=0}" \
  ctest --test-dir build-asan --output-on-failure -j"$(nproc)" -L "${unattributable_leaks}" \
  -E "^(${excluded})\$|^(${frame_timed})\."
stage "the live-view tests under ASan + UBSan, one at a time"
ASAN_OPTIONS="${ASAN_OPTIONS/detect_leaks=1/detect_leaks=0}" \
  ctest --test-dir build-asan --output-on-failure -j1 -L "${unattributable_leaks}" \
  -R "^(${frame_timed})\."

if [ "${fuzz_seconds}" != 0 ]; then
  stage "fuzzing, ${fuzz_seconds} s per harness"
  CONFVIS_FUZZ_BUILD=build-asan bash tests/fuzz/run.sh "${fuzz_seconds}"
fi
if [ "${CONFVIS_TSAN:-1}" != 0 ]; then
  stage "ThreadSanitizer"
  bash tools/sanitizers/tsan.sh
fi
stage "done"
