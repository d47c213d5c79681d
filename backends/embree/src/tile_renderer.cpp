#include "tile_renderer.hpp"

#include <algorithm>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "camera_packet.hpp"

namespace confvis::embree {

std::size_t tileCount(int width, int height, int tileSize) {
  const auto across = static_cast<std::size_t>((width + tileSize - 1) / tileSize);
  const auto down = static_cast<std::size_t>((height + tileSize - 1) / tileSize);
  return across * down;
}

namespace {

void renderTile(const EmbreeScene& scene, const CameraRays& rays, const TileJob& job, int x0,
                int y0, ImageRGBA& image, RayCounters& counters) {
  const int x1 = std::min(x0 + job.tileSize, job.width);
  const int y1 = std::min(y0 + job.tileSize, job.height);
  PacketSamples samples;
  PacketHits hits;
  PacketColours colours;
  std::uint64_t cameraRays = 0, occlusionRays = 0, retraced = 0;
  // Per-pixel random streams drive sub-pixel positions and occlusion rays only.
  const bool seeded = job.samplesPerPixel > 1 || job.shading.ambientOcclusion;
  const float scale = 1.0f / static_cast<float>(job.samplesPerPixel);
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; x += kPacketSize) {
      samples.x = x;
      samples.y = y;
      samples.count = std::min(kPacketSize, x1 - x);
      PacketColours sum;  // over the samples (several per pixel)
      if (seeded)
        for (int lane = 0; lane < samples.count; ++lane)
          samples.pixelSeeds[lane] = pixelSeed(job, x + lane, y);
      for (int sample = 0; sample < job.samplesPerPixel; ++sample) {
        samples.sample = sample;
        std::array<std::uint32_t, kPacketSize> sampleSeeds{};
        if (seeded)
          for (int lane = 0; lane < samples.count; ++lane)
            sampleSeeds[lane] =
                hashU32(samples.pixelSeeds[lane] + static_cast<std::uint32_t>(sample));
        cameraRays += traceCameraPacket(scene, rays, job, samples, hits);
        retraced += static_cast<std::uint64_t>(hits.retraced);
        occlusionRays += shadePacket(scene, hits, job.shading, sampleSeeds, colours);
        if (job.samplesPerPixel == 1) break;  // the colours are the pixels
        for (int lane = 0; lane < kPacketSize; ++lane) {
          sum.red[lane] += colours.red[lane];
          sum.green[lane] += colours.green[lane];
          sum.blue[lane] += colours.blue[lane];
          sum.alpha[lane] += colours.alpha[lane];
        }
      }
      const PacketColours& mean = job.samplesPerPixel == 1 ? colours : sum;
      for (int lane = 0; lane < samples.count; ++lane) {
        float* pixel = image.at(x + lane, y);
        pixel[0] = mean.red[lane] * scale;
        pixel[1] = mean.green[lane] * scale;
        pixel[2] = mean.blue[lane] * scale;
        pixel[3] = mean.alpha[lane] * scale;
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
  // Every pixel is written below: an image of the right size is rendered over as it is (a
  // frame loop's previous image, see renderInto), only a new one is allocated.
  if (image.width != job.width || image.height != job.height)
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
