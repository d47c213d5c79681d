#pragma once
// The image-based alternative to ray retargeting (what SGCT's fisheye path does): render a
// cube map around the reference point with ordinary perspective views, then resample it
// through the retarget map for every wall pixel. Used by the render benchmark as a baseline.
#include <vector>

#include "confvis/backends/render_backend.hpp"
#include "confvis/backends/wall_map_grid.hpp"

namespace confvis::bench {

// A display whose six walls are the faces of a cube map around `reference`, oriented so that
// wall pixel (x, y) is cube texel (x, y) of the face in confvis's (OpenEXR) layout.
DisplayConfig cubeFaceDisplay(int faceSize, const glm::dvec3& reference);

struct ImageBasedTimings {
  double cubeSeconds = 0, resampleSeconds = 0;
};

// The map seen from each wall of `config` at output scale `scale` (the same precomputation the
// direct path caches), built once before timing.
std::vector<WallMapGrid> wallGrids(const DisplayConfig& config, const ConformalWarp& warp,
                                   double scale);

// Renders the cube (plain, centre eye, `backend`'s scene) and resamples it onto every wall of
// `config` (centre eye, output size = wall resolution * scale) through the map in `grids`;
// unlit pixels are black. Images come in config order.
std::vector<WallImage> renderImageBased(RenderBackend& backend, const DisplayConfig& config,
                                        const std::vector<WallMapGrid>& grids, int faceSize,
                                        double scale, ImageBasedTimings& timings);

}  // namespace confvis::bench
