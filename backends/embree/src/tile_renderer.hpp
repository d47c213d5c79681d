#pragma once
// One wall image for one eye: the image is cut into square tiles rendered in parallel by TBB;
// inside a tile, runs of 8 neighbouring pixels form one ray packet per sample.
#include <atomic>
#include <cstdint>

#include "camera_rays.hpp"
#include "confvis/backends/embree/embree_scene.hpp"
#include "confvis/base/image.hpp"
#include "confvis/base/progress.hpp"
#include "sampling.hpp"
#include "shading.hpp"

namespace confvis::embree {

class DirectionTable;

struct RayCounters {
  std::atomic<std::uint64_t> camera{0};     // primary rays (one per path segment traced)
  std::atomic<std::uint64_t> occlusion{0};  // ambient-occlusion rays
  std::atomic<std::uint64_t> retraced{0};   // camera rays traced again (see tracePaths)
};

struct TileJob {
  int width = 0, height = 0;          // output pixels
  glm::dvec2 pixelToWall{1.0};        // output pixel units -> wall pixel units (scaled renders)
  int samplesPerPixel = 1;
  int tileSize = 16;
  std::uint32_t seed = 0;             // distinguishes images (wall, eye) in the random streams
  ShadingOptions shading;
  // Conformal rays of every sample, precomputed (see DirectionTable): the centre eye's map
  // directions, fast stereo rays' directions, or exact stereo rays' tails; null = the
  // CameraRays look the map up.
  const DirectionTable* directions = nullptr;
};

// The seed of output pixel (x, y)'s random streams (sub-pixel positions, occlusion rays).
inline std::uint32_t pixelSeed(const TileJob& job, int x, int y) {
  return hashU32(job.seed ^ hashU32(static_cast<std::uint32_t>(y) * 0x9e3779b1u +
                                    static_cast<std::uint32_t>(x)));
}

// Wall-pixel position of sample `sample` of output pixel (x, y): the stratified sub-pixel
// offset (seeded per pixel and image) scaled to wall pixels.
inline glm::dvec2 samplePosition(const TileJob& job, int x, int y, int sample,
                                 std::uint32_t seed) {
  const glm::dvec2 offset = stratifiedSample(sample, job.samplesPerPixel, seed);
  return {(x + offset.x) * job.pixelToWall.x, (y + offset.y) * job.pixelToWall.y};
}
inline glm::dvec2 samplePosition(const TileJob& job, int x, int y, int sample) {
  return samplePosition(job, x, y, sample, pixelSeed(job, x, y));
}

// Renders into `image`, kept if it is width x height already (every pixel is overwritten), else
// reallocated: linear RGB averaged over the samples, alpha = fraction of samples that hit
// something. Calls progress.advance() once per tile.
void renderTiles(const EmbreeScene& scene, const CameraRays& rays, const TileJob& job,
                 ImageRGBA& image, Progress& progress, RayCounters& counters);

// Tiles renderTiles will advance the progress by for a width x height image.
std::size_t tileCount(int width, int height, int tileSize);

}  // namespace confvis::embree
