#pragma once
// Screenshots of `confvis view` (8-bit PNGs of the presented frames) compared with each other or
// with the offline render of the same frame: the golden tolerance every view test uses.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>

#include "confvis/base/png_io.hpp"

namespace confvis::testing {

constexpr int kScreenshotTolerance = 2;         // 8-bit codes per channel
constexpr double kScreenshotBadBudget = 0.005;  // of a wall's pixels

// Pixels whose largest channel difference exceeds `tolerance` (8-bit codes), as a fraction.
// Images of different sizes are all bad.
inline double badPixelFraction(const std::filesystem::path& a, const std::filesystem::path& b,
                               int tolerance = kScreenshotTolerance) {
  const ImageRGBA x = readPng(a, PngDecoding::Raw);
  const ImageRGBA y = readPng(b, PngDecoding::Raw);
  if (x.width != y.width || x.height != y.height) return 1.0;
  std::size_t bad = 0;
  for (int row = 0; row < x.height; ++row)
    for (int col = 0; col < x.width; ++col) {
      double worst = 0.0;
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(double(x.at(col, row)[c]) - y.at(col, row)[c]) * 255.0);
      bad += worst > tolerance + 0.01;
    }
  return static_cast<double>(bad) / x.pixelCount();
}

}  // namespace confvis::testing
