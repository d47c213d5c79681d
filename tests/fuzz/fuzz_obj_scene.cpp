// OBJ scenes with their MTL (tinyobjloader behind obj_text's checks): the input is the OBJ text,
// then optionally a NUL byte and the MTL text, written beside the OBJ as scene.mtl (the name the
// seeds' `mtllib` gives). Without a NUL there is no MTL file (the loader warns, keeps white).
#include <cstdint>
#include <cstring>
#include <filesystem>

#include "confvis/base/error.hpp"
#include "confvis/engine/scene_loader.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto* nul = static_cast<const std::uint8_t*>(std::memchr(data, 0, size));
  const std::size_t objSize = nul ? static_cast<std::size_t>(nul - data) : size;
  if (nul)
    confvis::fuzz::writeInput("scene.mtl", nul + 1, size - objSize - 1);
  else
    std::filesystem::remove(confvis::fuzz::scratchFile("scene.mtl"));
  const auto file = confvis::fuzz::writeInput("input.obj", data, objSize);
  try {
    (void)confvis::loadScene(file);
  } catch (const confvis::Error&) {
  }
  return 0;
}
