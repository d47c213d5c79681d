#!/usr/bin/env bash
# Installs, builds and runs the whole test suite, then the sanitizer stage (tools/sanitize.sh):
# the suite again under ASan + UBSan (+ LSan), every fuzz harness for a bounded time, TSan over
# the threaded suites. This is what CI runs through .ci/run. CONFVIS_SANITIZE=0 skips the
# sanitizer stage (a quick local run); its cost on CI: tests/fuzz/README.md, "In CI".
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
if [ "${CONFVIS_SANITIZE:-1}" != 0 ]; then
  bash tools/sanitize.sh
fi
