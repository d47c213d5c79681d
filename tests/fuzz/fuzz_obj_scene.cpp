// OBJ scenes (tinyobjloader behind obj_text's checks). The MTL of the corpus files is not
// fuzzed here: the input is the OBJ text alone.
#include <cstdint>

#include "confvis/base/error.hpp"
#include "confvis/engine/scene_loader.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = confvis::fuzz::writeInput("input.obj", data, size);
  try {
    (void)confvis::loadScene(file);
  } catch (const confvis::Error&) {
  }
  return 0;
}
