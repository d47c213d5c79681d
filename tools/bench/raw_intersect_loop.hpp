#pragma once
// The throughput ceiling for the render benchmark: the same primary rays as a plain render,
// traced with a bare rtcIntersect8 loop (TBB tiles, 8-ray packets, no shading, no output). Ray
// generation and packet layout follow the renderer (16-pixel tiles, packets of 4 x 2 pixels,
// float affine directions), so the fraction of this loop's rate measures what
// shading, sampling and output cost, not a different traversal order.
#include <cstdint>

#include "confvis/backends/embree/embree_scene.hpp"
#include "confvis/engine/display_config.hpp"

namespace confvis::bench {

struct RawLoopResult {
  std::uint64_t rays = 0;
  std::uint64_t hits = 0;
  double seconds = 0;
};

// Centre-eye pixel-centre rays of every wall at `scale`, as plain rendering shoots them.
RawLoopResult rawIntersectLoop(const EmbreeScene& scene, const DisplayConfig& config,
                               double scale);

}  // namespace confvis::bench
