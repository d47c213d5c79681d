#!/usr/bin/env bash
# Runs the Vulkan checks by hand on a machine with a GPU driver but without Debian's packages,
# from the archive tools/bench/portable_bundle.sh made: the device list, the default CAVE render,
# the benchmark (GPU time from timestamps beside wall-clock time) and the Vulkan tests on that
# device. Never part of CI.
#   tools/bench/device_check.sh [ARCHIVE] [DEVICE] [OUTDIR] [STEPS]
#   (defaults: .device/bundle.tar.xz, auto (a discrete GPU first), $OUT or out/device-check,
#   render,bench,bench-full-resolution,tests,goldens)
# Step compare: the timing table of this benchmark and of BASELINE_BENCH (a confvis_bench_vulkan
# built from another commit, same libraries) alternately, two rounds each.
set -uo pipefail
archive=${1:-.device/bundle.tar.xz}
device=${2:-auto}
out=${3:-${OUT:-out/device-check}}
steps=,${4:-render,bench,bench-full-resolution,tests,goldens},
mkdir -p "$out"
root=$(mktemp -d)
tar -xJf "$archive" -C "$root" || { echo "device_check: cannot unpack $archive" >&2; exit 2; }
export LD_LIBRARY_PATH="$root/lib:/usr/local/nvidia/lib64:/usr/local/nvidia/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export VK_LAYER_PATH="$root/layers"
# The C++ runtime only where the machine's own is missing or older than the build's.
if ldd "$root/bin/confvis" | grep -q "not found"; then
  export LD_LIBRARY_PATH="$LD_LIBRARY_PATH:$root/lib-compat"
fi
for icd in /usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json /usr/share/vulkan/icd.d/nvidia_icd.json \
           /etc/vulkan/icd.d/nvidia_icd.json; do
  if [[ -e $icd ]]; then export VK_DRIVER_FILES=$icd VK_ICD_FILENAMES=$icd; break; fi
done
# The programs find configs/ and the goldens under the source directory they were built from;
# this checkout stands in for it where that path does not exist here.
src=$(cat "$root/source_dir.txt")
if [[ ! -e $src/configs ]]; then mkdir -p "$(dirname "$src")" && ln -sfn "$PWD" "$src"; fi
bin=$root/bin
step() {  # step NAME SECONDS COMMAND...: runs it under a time limit, logs to $out/NAME.txt
  local name=$1 limit=$2; shift 2
  [[ $steps == *,$name,* || ($name == compare-* && $steps == *,compare,*) ||
     ($name == tests-* && $steps == *,tests,*) ]] || return 0
  echo "== $name: $*"
  local start=$SECONDS
  timeout "$limit" "$@" >"$out/$name.txt" 2>&1
  local rc=$?
  tail -n 40 "$out/$name.txt"
  echo "== $name: exit $rc after $((SECONDS - start)) s"
}
{
  nvidia-smi -L 2>&1 || true
  echo "driver manifest: ${VK_DRIVER_FILES:-none}"; [[ -n ${VK_DRIVER_FILES:-} ]] && cat "$VK_DRIVER_FILES"
  echo "source dir: $src"
  ls /usr/local/nvidia/share/vulkan/icd.d /usr/share/vulkan/icd.d /etc/vulkan/icd.d 2>&1
  # The devices the loader found (its own errors beside them).
  VK_LOADER_DEBUG=error,warn "$root/bin/confvis" devices 2>&1 | head -n 30
} | tee "$out/environment.txt"
step render 60 "$bin/confvis" render --backend vulkan --device "$device" -o "$root/render"
cp "$root"/render/*front*.png "$root"/render/*left*.png "$out/" 2>/dev/null  # two walls' previews
step bench 200 "$bin/confvis_bench_vulkan" --device "$device" --repeats 15 --skip-zoom-sweep
# The display's own resolution; the readback of 5 float images dominates the wall clock there.
step bench-full-resolution 180 "$bin/confvis_bench_vulkan" --device "$device" --scale 1 \
  --repeats 9 --maps identity,baked --skip-sweep
for round in 1 2; do
  [[ -n ${BASELINE_BENCH:-} ]] || break
  step compare-baseline-$round 120 "$BASELINE_BENCH" --device "$device" --skip-sweep --repeats 25
  step compare-current-$round 120 "$bin/confvis_bench_vulkan" --device "$device" --skip-sweep \
    --repeats 25
done
# Each test suite in a process of its own: NVIDIA's driver 580 refused vkCreateInstance
# (VK_ERROR_INCOMPATIBLE_DRIVER) once one process had made and destroyed some 26-36 tests'
# instances (H100, H200), although every instance and device is destroyed (counted by hand).
export CONFVIS_TEST_VULKAN_DEVICE=$device
filter='Vulkan*:CubeMapVulkan*:BackendCrossCheck*:BackendPrepare*:FrameStats*:ReadmeLoop*:Backends/*:-VulkanDevice.*:*/VulkanGolden.*'
for suite in $("$bin/confvis_tests" --gtest_filter="$filter" --gtest_list_tests | grep -v '^ ' | grep -v '^Running' | tr -d .); do
  step "tests-${suite//\//-}" 150 "$bin/confvis_tests" --gtest_filter="$suite.*"
done
step goldens 150 "$bin/confvis_tests" --gtest_filter='BuiltinScenes/VulkanGolden*'
grep -HE "^\[  (PASSED|FAILED) " "$out"/tests-*.txt "$out"/goldens.txt 2>/dev/null ||
  true  # the goldens step may be left out
