#pragma once
// The retarget map seen from one wall: F(dir(p - c)) and the map's alpha sampled on a regular
// grid of points p of the wall's lit rectangle, for a cheap bilinear lookup at any sub-pixel
// position. Every conformal camera sample needs this value (centre eye: the ray direction;
// fast stereo rays: W(p); all eyes: whether a display is lit there); a grid at most half a map
// texel apart reproduces the cube-map lookup far below a pixel, at a fraction of its cost, and
// is reused across frames (the map and the walls do not change).
#include <vector>

#include <glm/glm.hpp>

#include "confvis/backends/conformal_warp.hpp"
#include "confvis/base/export.hpp"
#include "confvis/engine/display_config.hpp"

namespace confvis CONFVIS_API {

// Thread-safety: immutable once built; at() may be called from any number of threads at once.
class WallMapGrid {
 public:
  // Samples spaced about `spacing` wall pixels apart (exactly dividing the wall), corners
  // included.
  WallMapGrid(const ConformalWarp& warp, const Wall& wall, double spacing);

  struct Sample {
    glm::vec3 direction;  // F, interpolated: nearly but not exactly unit length
    float alpha;          // lit where >= 0.5
  };
  // At wall-pixel position (px, py), py = 0 at the top edge, px in [0, width], py in [0, height].
  Sample at(float px, float py) const;
  // at() for `count` positions at once, as structure of arrays (F's x, y, z and alpha per
  // position): the same floats as at() (its operations in its order), the blend done four
  // components at a time. For the stereo rays' per-packet lookups.
  void at(int count, const float* px, const float* py, float* x, float* y, float* z,
          float* alpha) const;

  // Spacing in wall pixels: half a map texel as seen from c where the wall is closest, but no
  // finer than one output pixel (1 / outputScale wall pixels).
  static double spacingFor(const Wall& wall, const glm::dvec3& reference, int mapResolution,
                           double outputScale);

  std::size_t sampleCount() const { return samples_.size(); }

  // Whether at() gives alpha >= 0.5 at every position of the box [px0, px1] x [py0, py1]
  // (wall pixels): every grid sample of the cells the box touches is lit with a margin (a
  // bilinear blend stays above its corners' least, up to rounding). False can still be lit.
  bool litThroughout(float px0, float py0, float px1, float py1) const;

 private:
  int columns_ = 1, rows_ = 1;         // cells
  float cellsPerPixelX_ = 1, cellsPerPixelY_ = 1;
  std::vector<glm::vec4> samples_;     // (columns + 1) x (rows + 1): F in xyz, alpha in w
};

}  // namespace confvis
