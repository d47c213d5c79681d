#pragma once
// Per-pixel image checks shared by the Vulkan tests and tools/bench/vulkan_bench.cpp (no gtest):
// two images against each other, and a render against a closed-form colour per view direction.
#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

#include <glm/glm.hpp>

#include "confvis/base/image.hpp"
#include "confvis/engine/view.hpp"

namespace confvis::test {

struct PixelComparison {
  std::size_t pixels = 0;  // compared
  std::size_t bad = 0;     // some channel off by more than the tolerance
  double maxError = 0.0;
  double badFraction() const { return pixels ? double(bad) / double(pixels) : 1.0; }
};

// Per-pixel comparison of all four channels; images of different sizes compare as all bad.
inline PixelComparison comparePixels(const ImageRGBA& a, const ImageRGBA& b, float tolerance) {
  PixelComparison c;
  c.pixels = a.pixelCount();
  if (a.width != b.width || a.height != b.height) {
    c.bad = c.pixels;
    c.maxError = 1e9;
    return c;
  }
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      double worst = 0.0;
      for (int k = 0; k < 4; ++k)
        worst = std::max(worst, double(std::abs(a.at(x, y)[k] - b.at(x, y)[k])));
      c.maxError = std::max(c.maxError, worst);
      if (worst > tolerance) ++c.bad;
    }
  return c;
}

// The colour a scene shows along a direction from the eye; nullopt where nothing is drawn.
using DirectionColor = std::function<std::optional<glm::vec3>(glm::dvec3)>;

// Pixels something was drawn on (alpha above 0).
inline std::size_t drawnPixels(const ImageRGBA& image) {
  std::size_t drawn = 0;
  for (std::size_t i = 0; i < image.pixelCount(); ++i) drawn += image.pixels[4 * i + 3] > 0.0f;
  return drawn;
}

struct AnalyticComparison {
  std::size_t pixels = 0, unambiguous = 0, bad = 0, empty = 0;
};

// Compares `image` (a render of `wall` seen from `eye`) with `expected` at every pixel whose
// centre and four half-pixel neighbours all expect the same (colours within half the tolerance,
// or nothing drawn: alpha 0); pixels on an edge are left out, since rasterization places edges
// only to within a pixel.
inline AnalyticComparison compareAnalytic(const ImageRGBA& image, const Wall& wall,
                                          glm::dvec3 eye, const DirectionColor& expected,
                                          float tolerance) {
  const WallView view = makeWallView(wall, eye);
  const double sx = double(wall.width) / image.width, sy = double(wall.height) / image.height;
  AnalyticComparison c;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      ++c.pixels;
      const auto colorAt = [&](double dx, double dy) {
        return expected(view.rayDirection((x + 0.5 + dx) * sx, (y + 0.5 + dy) * sy));
      };
      const std::optional<glm::vec3> centre = colorAt(0, 0);
      bool same = true;
      for (auto [dx, dy] : {std::pair{-0.5, 0.0}, {0.5, 0.0}, {0.0, -0.5}, {0.0, 0.5}}) {
        const std::optional<glm::vec3> other = colorAt(dx, dy);
        same = same && other.has_value() == centre.has_value() &&
               (!centre || glm::all(glm::lessThanEqual(glm::abs(*other - *centre),
                                                        glm::vec3(0.5f * tolerance))));
      }
      if (!same) continue;
      ++c.unambiguous;
      const float* p = image.at(x, y);
      const glm::vec4 want = centre ? glm::vec4(*centre, 1.0f) : glm::vec4(0.0f);
      if (!centre) ++c.empty;
      float error = 0.0f;
      for (int k = 0; k < 4; ++k) error = std::max(error, std::abs(p[k] - want[k]));
      if (error > tolerance) ++c.bad;
    }
  return c;
}

}  // namespace confvis::test
