// Cube-map EXR files (ray.exr / geom.exr of a baked directory): readCubeExr on the raw bytes.
#include <cstdint>

#include "confvis/base/cube_map.hpp"
#include "confvis/base/error.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto file = confvis::fuzz::writeInput("input.exr", data, size);
  try {
    (void)confvis::readCubeExr(file);
  } catch (const confvis::Error&) {
  }
  return 0;
}
