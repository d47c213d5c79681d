#pragma once
// The edge blend of overlapping projector walls (DisplayConfig::edgeBlend, the ramps of
// display_surfaces.hpp) applied to rendered wall images: the post step every backend's output
// goes through before it is written (confvis render, confvis walk, cluster runs alike).
//
// The mask acts on the signal a projector is fed, not on linear light: each pixel's colour is
// sRGB-encoded (the 8-bit signal the PNG previews and a display receive), scaled by the wall's
// mask weight^(1/gamma), and decoded back to linear, so a projector whose response is
// signal^gamma emits weight times its light and overlapping projectors sum to one. Alpha is kept.
#include <string>
#include <unordered_map>
#include <vector>

#include "confvis/base/export.hpp"
#include "confvis/backends/render_backend.hpp"

namespace confvis CONFVIS_API {

// Thread-safety: not thread-safe: apply() fills its mask cache; one thread at a time.
class EdgeBlender {
 public:
  explicit EdgeBlender(DisplayConfig config);

  bool active() const { return !blendedWalls_.empty(); }
  // Blends every image whose wall needs it (at the image's size: --scale renders smaller).
  // Masks are computed on first use per wall and size, then kept: not thread-safe.
  void apply(std::vector<WallImage>& images) const;

 private:
  struct Mask {
    int width = 0, height = 0;
    std::vector<float> factors;
  };
  DisplayConfig config_;
  std::unordered_map<std::string, int> blendedWalls_;  // name -> index into config_.walls
  mutable std::unordered_map<std::string, Mask> masks_;
};

}  // namespace confvis
