// Mesh files for `confvis flow`: the first byte picks OBJ, OFF, PLY or STL, the rest is the file.
#include <cstdint>

#include "confvis/base/error.hpp"
#include "confvis/conformal/mesh.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const char* const kNames[4] = {"input.obj", "input.off", "input.ply", "input.stl"};
  const auto file = confvis::fuzz::writeInput(kNames[data[0] % 4], data + 1, size - 1);
  try {
    (void)confvis::conformal::readMesh(file);
  } catch (const confvis::Error&) {
  }
  return 0;
}
