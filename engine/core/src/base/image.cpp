#include "confvis/base/image.hpp"

#include <algorithm>
#include <cmath>

namespace confvis {

bool ImageRGBA::allFinite() const {
  return std::all_of(pixels.begin(), pixels.end(), [](float v) { return std::isfinite(v); });
}

}  // namespace confvis
