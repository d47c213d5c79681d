#include "confvis/runtime/window_content.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "confvis/base/error.hpp"
#include "confvis/base/png_io.hpp"

namespace confvis {

namespace {

// linearToSrgb per channel is a pow per value; instead, the 255 linear values at which the
// rounded code goes up (writePng's lround(255 * linearToSrgb(v))) are searched.
struct SrgbTable {
  std::array<float, 256> threshold{};  // linear value from which code k+1 is nearer
  SrgbTable() {
    // Code k covers [srgbToLinear((k - 0.5) / 255), srgbToLinear((k + 0.5) / 255)).
    for (int k = 0; k < 255; ++k) threshold[k] = srgbToLinear((k + 0.5f) / 255.0f);
    threshold[255] = 2.0f;
  }
  std::uint8_t code(float linear) const {
    if (!(linear > 0.0f)) return 0;
    if (linear >= 1.0f) return 255;
    // Binary search of the 255 thresholds: 8 comparisons, no pow.
    const auto it = std::upper_bound(threshold.begin(), threshold.end() - 1, linear);
    return static_cast<std::uint8_t>(it - threshold.begin());
  }
};

const SrgbTable& table() {
  static const SrgbTable instance;
  return instance;
}

}  // namespace

std::uint8_t srgbCode(float linear) { return table().code(linear); }

void composeWindow(const WindowPlan& plan, const std::function<const ImageRGBA*(Eye)>& imageOf,
                   std::uint8_t* out) {
  const SrgbTable& srgb = table();
  for (const EyeRegion& region : plan.regions) {
    const ImageRGBA* image = imageOf(region.eye);
    if (!image || image->width != region.width || image->height != region.height)
      throw Error(ErrorCode::Internal,
                  "wall '" + plan.wall + "': the rendered image is not the " +
                      std::to_string(region.width) + "x" + std::to_string(region.height) +
                      " its window expects");
    for (int y = 0; y < region.height; ++y) {
      const float* source = image->at(0, y);
      std::uint8_t* target =
          out + (static_cast<std::size_t>(region.y + y) * plan.contentWidth + region.x) * 4;
      for (int x = 0; x < region.width; ++x, source += 4, target += 4) {
        target[0] = srgb.code(source[0]);
        target[1] = srgb.code(source[1]);
        target[2] = srgb.code(source[2]);
        target[3] = 255;
      }
    }
  }
}

}  // namespace confvis
