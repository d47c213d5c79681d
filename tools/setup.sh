#!/usr/bin/env bash
# Installs everything confvis needs to build and test on Debian 12 (bookworm), as root.
# Debian packages only; no downloads besides apt.
set -euo pipefail
packages=(
  # toolchain
  build-essential cmake ninja-build pkg-config git
  # the sanitizer and fuzzing builds (tools/sanitize.sh, tests/fuzz): clang with its ASan, UBSan,
  # TSan and libFuzzer runtimes
  clang-14 libclang-rt-14-dev
  # rendering: Vulkan (lavapipe for headless CI), shader compiler, Embree
  mesa-vulkan-drivers libvulkan-dev vulkan-validationlayers glslang-tools glslang-dev spirv-tools
  libembree-dev libtbb-dev
  # geometry and numerics
  libglm-dev libopenmesh-dev libeigen3-dev
  # image and scene I/O: EXR, PNG previews, OBJ and glTF loaders (tinygltf uses stb + nlohmann)
  libopenexr-dev libpng-dev libtinyobjloader-dev libtinygltf-dev libstb-dev nlohmann-json3-dev
  # XML display descriptions (ParaView .pvx, SGCT's older XML); ParaView itself reads .pvx with it
  libpugixml-dev
  # CLI parsing and tests
  libcli11-dev libgtest-dev
  # cluster rendering (--cluster, confvis::Cluster): Open MPI and its mpirun
  libopenmpi-dev openmpi-bin
  # live display (confvis view): GLFW windows; its tests run under Xvfb and drive the windows
  # through Xlib (close, resize)
  libglfw3-dev libx11-dev xvfb xauth
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
echo "setup: all ${#packages[@]} packages present"
