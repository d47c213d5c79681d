#pragma once
// Exact stereo rays' tails from an eye-independent grid over one wall's plane (issue 23).
//
// With W(x) = c + |x - c| F(dir(x - c)), the eye ray x = e + t v (v unit) has, as t -> infinity,
// the asymptote  c + M(v) w + s F(v),  w = e - c,  M(v) = d/dx F(x / |x|) at x = v (M(v) v = 0):
// linear in w, first derivatives only. The ray from c along v = dir(p - e), p a pixel's wall
// point, meets the wall's plane at q = c + (d_c / d_e) (p - e): affine in the pixel position. So
// F and M are stored once per map over the wall's plane in q (wall pixels, the lit rectangle's
// pixel frame, extended by a margin past its edges for eyes away from c), and a frame reads them
// with one bilinear lookup per sample, whatever the eye.
//
// M is stored as its images of the plane's unit right and up vectors, A = M(v) r and B = M(v) u:
// with x = q - c, M(v) = |x| dF(x/|x|)/dx and M x = 0, so A = |x| dG/dr, B = |x| dG/du for
// G(q) = F(dir(q - c)) (central differences of the cube map, one F-node spacing each side), and
// M(v) w = a A + b B where w = a r + b u + gamma x (gamma = w.n / x.n is the same all over the
// plane, a and b are affine in q). F is sampled a map texel apart (kFCoarsening);
// A and B, which move a hit r from c by |dA a + dB b| / r <= |dM| sin(4e-3) (hits lie beyond
// h / sin(4e-3), h = |w| sin(angle(v, w))), on a grid kMomentStride times coarser.
#include <vector>

#include <glm/glm.hpp>

#include "confvis/backends/conformal_warp.hpp"
#include "confvis/backends/wall_map_grid.hpp"
#include "confvis/engine/display_config.hpp"

namespace confvis::embree {

class TailGrid {
 public:
  // Every how many F nodes an A, B node lies.
  static constexpr int kMomentStride = 4;

  // F nodes kFCoarsening times as far apart as the WallMapGrid's (spacingFor): the tails are
  // read at the lattice's nodes, 4 output pixels apart (tail_lattice.hpp), and a grid that
  // fits in the caches costs less than its interpolation error (EmbreeTailGrid.*).
  static constexpr double kFCoarsening = 2.0;
  static double spacingFor(const Wall& wall, const glm::dvec3& reference, int mapResolution,
                           double outputScale);

  // `spacing`: F nodes about that many wall pixels apart (spacingFor); `margin`:
  // metres past each edge of the lit rectangle that the grid covers.
  TailGrid(const ConformalWarp& warp, const Wall& wall, double spacing, double margin);

  // For 8 positions q (wall pixels): F (not normalised) at [0, 24), A at [24, 48) and B at
  // [48, 72), each component's 8 lanes in turn. False, with nothing written, where one of the
  // first `count` lies outside the grid (later lanes are clamped into it).
  bool at(const float* qx, const float* qy, int count, float* out) const;

  std::size_t bytes() const { return (f_.size() + moments_.size()) * sizeof(glm::vec4); }

 private:
  float originX_ = 0, originY_ = 0;  // the first node's q, wall pixels
  float nodesPerPixelX_ = 1, nodesPerPixelY_ = 1;
  int across_ = 0, down_ = 0;                // F nodes per row, rows
  int momentsAcross_ = 0, momentsDown_ = 0;  // A, B nodes
  std::vector<glm::vec4> f_;        // F in xyz
  std::vector<glm::vec4> moments_;  // A, B: two vec4 per node
};

}  // namespace confvis::embree
