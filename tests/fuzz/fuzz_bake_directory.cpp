// Baked map directories: the input is bake.json; ray.exr and geom.exr are a valid 8-texel map,
// so every listed-file, checksum, type and resolution check runs against mutated sidecars.
#include <cstdint>
#include <filesystem>
#include <fstream>

#include "confvis/base/error.hpp"
#include "confvis/conformal/bake_files.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path dir = [] {
    const auto d = confvis::fuzz::scratchFile("bake");
    confvis::writeRetargetMapDirectory(d, confvis::RetargetMap::identity(8, {0, 0, 0}));
    return d;
  }();
  std::ofstream(dir / "bake.json", std::ios::binary)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  try {
    (void)confvis::loadBakeDirectory(dir);
  } catch (const confvis::Error&) {
  }
  return 0;
}
