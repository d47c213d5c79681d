// glTF: the first byte picks .gltf (even) or .glb (odd), the rest is the file.
#include <cstdint>

#include "confvis/base/error.hpp"
#include "confvis/engine/scene_loader.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const auto file = confvis::fuzz::writeInput((data[0] & 1) ? "input.glb" : "input.gltf", data + 1, size - 1);
  try {
    (void)confvis::loadScene(file);
  } catch (const confvis::Error&) {
  }
  return 0;
}
