#!/usr/bin/env bash
# Packs built confvis programs with the shared libraries they load (not the C library's own) and
# the Vulkan validation layer into one archive, for a lent machine that has a GPU driver but not
# Debian's packages (see tools/bench/device_check.sh, which unpacks and runs it there).
#   tools/bench/portable_bundle.sh [BUILD_DIR] [ARCHIVE]   (defaults: build, .device/bundle.tar.xz)
set -euo pipefail
build=${1:-build}
archive=${2:-.device/bundle.tar.xz}
programs=(confvis confvis_tests confvis_bench_vulkan)
for p in "${programs[@]}"; do
  [[ -x $build/$p ]] || { echo "portable_bundle: $build/$p is not built" >&2; exit 2; }
done
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/bin" "$stage/lib" "$stage/lib-compat" "$stage/layers"
for p in "${programs[@]}"; do
  strip -o "$stage/bin/$p" "$build/$p"
  # The target's glibc is newer and backward compatible: carrying ours would break its driver.
  ldd "$build/$p" | awk '$3 ~ /^\// {print $3}' |
    grep -vE '/(libc|libm|libdl|librt|libpthread|ld-linux[^/]*)\.so' |
    while read -r lib; do cp -Ln "$lib" "$stage/lib/" 2>/dev/null || true; done
done
# The C++ runtime apart: device_check.sh uses it only where the machine's own is missing or older
# (a newer one serves our programs and the GPU driver alike).
mv "$stage"/lib/libstdc++.so.* "$stage"/lib/libgcc_s.so.* "$stage/lib-compat/"
# libglvnd's dispatch libraries: NVIDIA's Vulkan driver (libGLX_nvidia) loads them.
for lib in libGLdispatch.so.0 libGLX.so.0 libEGL.so.1 libGL.so.1 libOpenGL.so.0; do
  [[ -e /usr/lib/x86_64-linux-gnu/$lib ]] && cp -L /usr/lib/x86_64-linux-gnu/$lib "$stage/lib/"
done
layer=/usr/lib/x86_64-linux-gnu/libVkLayer_khronos_validation.so
manifest=/usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json
if [[ -e $layer && -e $manifest ]]; then
  strip -o "$stage/layers/libVkLayer_khronos_validation.so" "$layer"
  # The manifest names the library by file name; make it the bundled one's path relative to it.
  sed 's#"library_path": *"[^"]*"#"library_path": "./libVkLayer_khronos_validation.so"#' \
    "$manifest" >"$stage/layers/VkLayer_khronos_validation.json"
fi
# The programs read configs/ and the goldens from the source directory they were built from.
sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$build/CMakeCache.txt" >"$stage/source_dir.txt"
mkdir -p "$(dirname "$archive")"
tar -C "$stage" -cf - . | xz -T0 -6 >"$archive.tmp"
mv "$archive.tmp" "$archive"
echo "portable_bundle: $archive ($(du -h "$archive" | cut -f1)): ${programs[*]}, $(ls "$stage/lib" | wc -l) libraries"
