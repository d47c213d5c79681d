#!/usr/bin/env bash
# The sanitizer stage of CI (run by tools/test.sh after the normal build and tests):
#   1. build-asan/: clang-14, AddressSanitizer + UndefinedBehaviorSanitizer (+ LeakSanitizer),
#      every object also with -fsanitize=fuzzer-no-link so the same build links the libFuzzer
#      harnesses of tests/fuzz; the whole test suite runs there (but for the packaging tests in
#      $excluded);
#   2. every fuzz harness for CONFVIS_FUZZ_SECONDS (default 20) from its seed corpus
#      (tests/fuzz/run.sh; 0 skips it);
#   3. ThreadSanitizer over the threaded suites (tools/sanitizers/tsan.sh; CONFVIS_TSAN=0 skips).
# Any sanitizer report, leak or fuzz finding fails the run (tools/sanitizers/env.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
fuzz_seconds="${CONFVIS_FUZZ_SECONDS:-20}"
stage() { echo "sanitize: $1 ($(date -u +%T), ${SECONDS} s since start)"; }

# Left out: they test packaging with the system compiler (an installed package built into an
# outside project, confvis as a subproject, the symbols an AVX2 object exports), which the normal
# build already ran; with instrumented objects they would only test the instrumentation.
excluded='consumer_package|subproject_with_makefiles|embree_avx2_object_exports_only_its_kernel'

flags="-O1 -gline-tables-only -fno-omit-frame-pointer -fsanitize=address,undefined"
flags+=" -fno-sanitize-recover=all -fsanitize=fuzzer-no-link"
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
stage "building build-asan"
# Build type "Sanitize": no preset flags of its own (so assertions stay on), all in $flags.
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Sanitize -DCMAKE_CXX_COMPILER=clang++-14 \
  "-DCMAKE_CXX_FLAGS=${flags}" -DCONFVIS_WERROR=OFF -DCONFVIS_FUZZ=ON "${launcher[@]}" >/dev/null
cmake --build build-asan -j"$(nproc)"

# Tests that load a Vulkan driver (lavapipe, its LLVM, the validation layer) or start Open MPI run
# with ASan and UBSan but without LeakSanitizer: the Vulkan loader and Open MPI dlclose those
# modules before exit, so their leaks show as "<unknown module>" and no suppression can name them.
unattributable_leaks='Vulkan|Lavapipe|ClusterCli'

source tools/sanitizers/env.sh
stage "the test suite under ASan + UBSan"
ctest --test-dir build-asan --output-on-failure -j"$(nproc)" -E "^(${excluded})\$|${unattributable_leaks}"
ASAN_OPTIONS="${ASAN_OPTIONS/detect_leaks=1/detect_leaks=0}" \
  ctest --test-dir build-asan --output-on-failure -j"$(nproc)" -R "${unattributable_leaks}" \
  -E "^(${excluded})\$"

if [ "${fuzz_seconds}" != 0 ]; then
  stage "fuzzing, ${fuzz_seconds} s per harness"
  CONFVIS_FUZZ_BUILD=build-asan bash tests/fuzz/run.sh "${fuzz_seconds}"
fi
if [ "${CONFVIS_TSAN:-1}" != 0 ]; then
  stage "ThreadSanitizer"
  bash tools/sanitizers/tsan.sh
fi
stage "done"
