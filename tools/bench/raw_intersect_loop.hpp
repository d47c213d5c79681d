#pragma once
// The throughput ceiling for the render benchmark: the same primary rays as a plain render,
// traced with a bare rtcIntersect8 loop (TBB tiles, 8-ray packets, no shading, no output). Ray
// generation and packet layout follow the renderer (16-pixel tiles, packets of 4 x 2 pixels,
// float affine directions), so the fraction of this loop's rate measures what
// shading, sampling and output cost, not a different traversal order.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "confvis/backends/embree/embree_scene.hpp"
#include "confvis/conformal/retarget_map.hpp"
#include "confvis/engine/display_config.hpp"

namespace confvis::bench {

struct RawLoopResult {
  std::uint64_t rays = 0;
  std::uint64_t hits = 0;
  double seconds = 0;
};

// Unit centre-eye directions of every wall's output pixels at `scale`, row by row (zero where
// unlit), built once before timing as the renderer builds its direction table.
struct DirectionTables {
  std::vector<std::vector<glm::vec3>> walls;
};
// The conformal ones: F at the pixel centre through the wall's WallMapGrid, as the renderer's
// direction table holds them.
DirectionTables conformalDirections(const RetargetMap& map, const DisplayConfig& config,
                                    double scale);
// The plain ones, as plain rendering shoots them: read from a table like the conformal ones, a
// loop over them differs from one over the conformal rays in the rays alone.
DirectionTables plainDirections(const DisplayConfig& config, double scale);

// Centre-eye pixel-centre rays of every wall at `scale`: plain ones as plain rendering shoots
// them or, given `table`, its directions (unlit pixels not traced). The loop over the conformal
// table is the fair ceiling of a conformal render: its rays cross the squeezed parts of the
// scene too.
RawLoopResult rawIntersectLoop(const EmbreeScene& scene, const DisplayConfig& config,
                               double scale, const DirectionTables* table = nullptr);

// The same loops with the renderer's own packet width: two 4 x 2 packets (4 x 4 pixels, lanes
// as the renderer packs them) per rtcIntersect16. The like-for-like ceiling of the renderer,
// which traces so (the goal names the rtcIntersect8 loop above).
RawLoopResult rawIntersect16Loop(const EmbreeScene& scene, const DisplayConfig& config,
                                 double scale, const DirectionTables* table = nullptr);

}  // namespace confvis::bench
