// Compares the top rows of the side walls of two `confvis render` outputs (issue 23, point 5: the
// top rim of cave5's side walls, where Vulkan left black notches and Embree draws a clean edge).
// Per wall: pixels black in the first (RGB exactly 0 in its PNG preview) and not in the second,
// and pixels whose 8-bit preview codes differ by more than --codes in any of R, G, B.
//   confvis render configs/cave5.json --backend vulkan --scale 0.5 -o VK
//   confvis render configs/cave5.json --backend embree --scale 0.5 -o EMBREE
//   confvis_bench_rim_black_count VK EMBREE
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "confvis/base/error.hpp"
#include "confvis/base/png_io.hpp"

namespace {

bool black(const float* p) { return p[0] == 0.0f && p[1] == 0.0f && p[2] == 0.0f; }

int code(float value) { return static_cast<int>(std::lround(value * 255.0f)); }

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Count pixels black in one render and not in another, top rows of each wall"};
  std::string first, second;
  std::vector<std::string> walls{"left", "front", "right", "back"};
  int rows = 24, codes = 25;
  app.add_option("first", first, "Output directory of the render under test (e.g. Vulkan)")
      ->required()->check(CLI::ExistingDirectory);
  app.add_option("second", second, "Output directory of the reference render (e.g. Embree)")
      ->required()->check(CLI::ExistingDirectory);
  app.add_option("--walls", walls, "Walls to compare (their <name>.png previews)")
      ->capture_default_str();
  app.add_option("--rows", rows, "Top rows of each wall to compare")
      ->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--codes", codes, "8-bit preview codes a channel may differ by")
      ->capture_default_str()->check(CLI::NonNegativeNumber);
  CLI11_PARSE(app, argc, argv);
  try {
    std::printf("%-8s %8s %10s %10s\n", "wall", "pixels", "black_only", "off_codes");
    for (const std::string& wall : walls) {
      const auto a = confvis::readPng(std::filesystem::path(first) / (wall + ".png"),
                                      confvis::PngDecoding::Raw);
      const auto b = confvis::readPng(std::filesystem::path(second) / (wall + ".png"),
                                      confvis::PngDecoding::Raw);
      if (a.width != b.width || a.height != b.height)
        throw confvis::Error(confvis::ErrorCode::InvalidInput,
                             "wall '" + wall + "': the two renders differ in size");
      long blackOnly = 0, off = 0, pixels = 0;
      for (int y = 0; y < std::min(rows, a.height); ++y)
        for (int x = 0; x < a.width; ++x) {
          const float* p = a.at(x, y);
          const float* q = b.at(x, y);
          ++pixels;
          blackOnly += black(p) && !black(q);
          bool differs = false;
          for (int c = 0; c < 3; ++c) differs |= std::abs(code(p[c]) - code(q[c])) > codes;
          off += differs;
        }
      std::printf("%-8s %8ld %10ld %10ld\n", wall.c_str(), pixels, blackOnly, off);
    }
  } catch (const confvis::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
