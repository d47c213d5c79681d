#include "confvis/backends/edge_blend_output.hpp"

#include <utility>

#include "confvis/base/png_io.hpp"
#include "confvis/engine/display_surfaces.hpp"

namespace confvis {

EdgeBlender::EdgeBlender(DisplayConfig config) : config_(std::move(config)) {
  if (!config_.edgeBlend.enabled) return;
  for (const DisplaySurface& surface : displaySurfaces(config_))
    if (surface.walls.size() > 1)
      for (int w : surface.walls) blendedWalls_.emplace(config_.walls[w].name, w);
}

void EdgeBlender::apply(std::vector<WallImage>& images) const {
  for (WallImage& image : images) {
    const auto wall = blendedWalls_.find(image.wall);
    if (wall == blendedWalls_.end() || image.image.empty()) continue;
    Mask& mask = masks_[image.wall];
    if (mask.width != image.image.width || mask.height != image.image.height) {
      mask.width = image.image.width, mask.height = image.image.height;
      mask.factors = edgeBlendSignal(config_, wall->second, mask.width, mask.height);
    }
    for (std::size_t p = 0; p < mask.factors.size(); ++p) {
      const float factor = mask.factors[p];
      if (factor >= 1.0f) continue;
      float* rgba = image.image.pixels.data() + 4 * p;
      for (int c = 0; c < 3; ++c) rgba[c] = srgbToLinear(linearToSrgb(rgba[c]) * factor);
    }
  }
}

}  // namespace confvis
