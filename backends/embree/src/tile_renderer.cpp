#include "tile_renderer.hpp"

#include <algorithm>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "direction_table.hpp"
#include "sampling.hpp"

namespace confvis::embree {

std::size_t tileCount(int width, int height, int tileSize) {
  const auto across = static_cast<std::size_t>((width + tileSize - 1) / tileSize);
  const auto down = static_cast<std::size_t>((height + tileSize - 1) / tileSize);
  return across * down;
}

namespace {

std::uint32_t pixelSeed(const TileJob& job, int x, int y) {
  return hashU32(job.seed ^ hashU32(static_cast<std::uint32_t>(y) * 0x9e3779b1u +
                                    static_cast<std::uint32_t>(x)));
}

}  // namespace

glm::dvec2 samplePosition(const TileJob& job, int x, int y, int sample) {
  const glm::dvec2 offset = stratifiedSample(sample, job.samplesPerPixel, pixelSeed(job, x, y));
  return {(x + offset.x) * job.pixelToWall.x, (y + offset.y) * job.pixelToWall.y};
}

namespace {


void renderTile(const EmbreeScene& scene, const CameraRays& rays, const TileJob& job, int x0,
                int y0, ImageRGBA& image, RayCounters& counters) {
  const int x1 = std::min(x0 + job.tileSize, job.width);
  const int y1 = std::min(y0 + job.tileSize, job.height);
  std::array<RayPath, kPacketSize> paths;
  std::array<std::uint32_t, kPacketSize> seeds{};
  std::array<glm::vec3, kPacketSize> colours{};
  PacketHits hits;
  std::uint64_t cameraRays = 0, occlusionRays = 0, retraced = 0;
  // Per-pixel random streams drive sub-pixel positions and occlusion rays only.
  const bool seeded = job.samplesPerPixel > 1 || job.shading.ambientOcclusion;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; x += kPacketSize) {
      const int count = std::min(kPacketSize, x1 - x);
      std::array<glm::vec4, kPacketSize> sum{};
      if (seeded)
        for (int lane = 0; lane < count; ++lane) seeds[lane] = pixelSeed(job, x + lane, y);
      for (int sample = 0; sample < job.samplesPerPixel; ++sample) {
        std::array<std::uint32_t, kPacketSize> sampleSeeds{};
        for (int lane = 0; lane < count; ++lane) {
          if (job.directions) {
            rays.makeCentre(job.directions->at(x + lane, y, sample), paths[lane]);
          } else {
            const glm::dvec2 offset = stratifiedSample(sample, job.samplesPerPixel, seeds[lane]);
            rays.make((x + lane + offset.x) * job.pixelToWall.x,
                      (y + offset.y) * job.pixelToWall.y, paths[lane]);
          }
          if (seeded) sampleSeeds[lane] = hashU32(seeds[lane] + static_cast<std::uint32_t>(sample));
        }
        cameraRays += tracePaths(scene.handle(), paths.data(), count, hits);
        retraced += static_cast<std::uint64_t>(hits.retraced);
        occlusionRays += shadePacket(scene, hits, job.shading, sampleSeeds, colours);
        for (int lane = 0; lane < count; ++lane)
          if (hits.hit[lane]) sum[lane] += glm::vec4(colours[lane], 1.0f);
      }
      const float scale = 1.0f / static_cast<float>(job.samplesPerPixel);
      for (int lane = 0; lane < count; ++lane) {
        float* pixel = image.at(x + lane, y);
        for (int c = 0; c < 4; ++c) pixel[c] = sum[lane][c] * scale;
      }
    }
  }
  counters.camera += cameraRays;
  counters.occlusion += occlusionRays;
  counters.retraced += retraced;
}

}  // namespace

void renderTiles(const EmbreeScene& scene, const CameraRays& rays, const TileJob& job,
                 ImageRGBA& image, Progress& progress, RayCounters& counters) {
  image = ImageRGBA(job.width, job.height, 0.0f);
  const int across = (job.width + job.tileSize - 1) / job.tileSize;
  const int tiles = static_cast<int>(tileCount(job.width, job.height, job.tileSize));
  tbb::parallel_for(tbb::blocked_range<int>(0, tiles, 1), [&](const tbb::blocked_range<int>& r) {
    for (int t = r.begin(); t != r.end(); ++t) {
      renderTile(scene, rays, job, (t % across) * job.tileSize, (t / across) * job.tileSize,
                 image, counters);
      progress.advance();
    }
  });
}

}  // namespace confvis::embree
