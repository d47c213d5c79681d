#include "tile_renderer.hpp"

#include <algorithm>
#include <vector>

#if defined(__SSE2__)
#include <immintrin.h>
#endif
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "camera_packet.hpp"
#include "tail_lattice.hpp"

namespace confvis::embree {

std::size_t tileCount(int width, int height, int tileSize) {
  const auto across = static_cast<std::size_t>((width + tileSize - 1) / tileSize);
  const auto down = static_cast<std::size_t>((height + tileSize - 1) / tileSize);
  return across * down;
}

namespace {

// The colours of lanes first .. first + count - 1 as RGBA pixels from `pixel` on, four lanes at a
// time transposed with shuffles. (Non-temporal stores, which skip reading the image's lines in,
// gained nothing: see the README.)
void storeRun(const PacketColours& c, int first, int count, float* pixel) {
  int lane = first;
  const int end = first + count;
#if defined(__SSE2__)
  for (; lane + 4 <= end; lane += 4, pixel += 16) {
    __m128 r = _mm_load_ps(&c.red[lane]), g = _mm_load_ps(&c.green[lane]);
    __m128 b = _mm_load_ps(&c.blue[lane]), a = _mm_load_ps(&c.alpha[lane]);
    _MM_TRANSPOSE4_PS(r, g, b, a);
    _mm_storeu_ps(pixel, r);
    _mm_storeu_ps(pixel + 4, g);
    _mm_storeu_ps(pixel + 8, b);
    _mm_storeu_ps(pixel + 12, a);
  }
#endif
  for (; lane < end; ++lane, pixel += 4) {
    pixel[0] = c.red[lane], pixel[1] = c.green[lane];
    pixel[2] = c.blue[lane], pixel[3] = c.alpha[lane];
  }
}

// A packet's colours into its block of the image, row by row.
void storePixels(const PacketColours& c, const PacketSamples& samples, ImageRGBA& image) {
  if (samples.count == kPacketSize && samples.columns == kBlockColumns) {  // a whole block
    storeRun(c, 0, kBlockColumns, image.at(samples.x, samples.y));
    storeRun(c, kBlockColumns, kBlockColumns, image.at(samples.x, samples.y + 1));
    return;
  }
  for (int first = 0; first < samples.count; first += samples.columns)
    storeRun(c, first, samples.columns, image.at(samples.x, samples.laneY(first)));
}

// One sample per pixel, at its centre: the packet's colours are the pixels.
void renderTileSingleSample(const EmbreeScene& scene, const CameraRays& rays, const TileJob& job,
                            int x0, int y0, ImageRGBA& image, RayCounters& counters) {
  const int x1 = std::min(x0 + job.tileSize, job.width);
  const int y1 = std::min(y0 + job.tileSize, job.height);
  std::array<PacketHits, 2> hits;
  PacketColours colours;
  std::array<std::uint32_t, kPacketSize> sampleSeeds{};  // occlusion rays only
  std::uint64_t cameraRays = 0, occlusionRays = 0, retraced = 0;
  TailLattice tails(rays, job, x0, y0, x1, y1);  // evaluated only if exact tails are asked for
  // Two packets (4 x 4 pixels) traced at once (traceCameraPacketPair), then shaded one by one.
  for (int y = y0; y < y1; y += 2 * kBlockRows) {
    for (int x = x0; x < x1; x += kBlockColumns) {
      std::array<PacketSamples, 2> samples = {blockAt(x, y, x1, y1), PacketSamples{}};
      if (y + kBlockRows < y1) samples[1] = blockAt(x, y + kBlockRows, x1, y1);
      cameraRays += traceCameraPacketPair(scene, rays, job, samples, hits, &tails);
      for (int half = 0; half < 2 && samples[half].count > 0; ++half) {
        const PacketSamples& packet = samples[half];
        if (job.shading.ambientOcclusion)  // the supersampled loop's seeds of sample 0
          for (int lane = 0; lane < packet.count; ++lane)
            sampleSeeds[lane] = hashU32(pixelSeed(job, packet.laneX(lane), packet.laneY(lane)));
        retraced += static_cast<std::uint64_t>(hits[half].retraced);
        occlusionRays += shadePacket(scene, hits[half], job.shading, sampleSeeds, colours);
        storePixels(colours, packet, image);
      }
    }
  }
  counters.camera += cameraRays;
  counters.occlusion += occlusionRays;
  counters.retraced += retraced;
}

// Several samples per pixel at stratified positions (seeded per pixel), averaged.
void renderTileSupersampled(const EmbreeScene& scene, const CameraRays& rays,
                            const TileJob& job, int x0, int y0, ImageRGBA& image,
                            RayCounters& counters) {
  const int x1 = std::min(x0 + job.tileSize, job.width);
  const int y1 = std::min(y0 + job.tileSize, job.height);
  std::array<PacketHits, 2> hits;
  PacketColours colours;
  std::uint64_t cameraRays = 0, occlusionRays = 0, retraced = 0;
  const float scale = 1.0f / static_cast<float>(job.samplesPerPixel);
  TailLattice tails(rays, job, x0, y0, x1, y1);
  for (int y = y0; y < y1; y += kBlockRows) {
    for (int x = x0; x < x1; x += kBlockColumns) {
      PacketSamples samples = blockAt(x, y, x1, y1);
      PacketColours mean;  // the sum over the samples, then scaled
      for (int lane = 0; lane < samples.count; ++lane)
        samples.pixelSeeds[lane] = pixelSeed(job, samples.laneX(lane), samples.laneY(lane));
      // Two samples of the packet traced at once (traceCameraPacketPair), summed in order.
      for (int first = 0; first < job.samplesPerPixel; first += 2) {
        std::array<PacketSamples, 2> pair = {samples, samples};
        pair[0].sample = first;
        pair[1].sample = first + 1;
        if (first + 1 == job.samplesPerPixel) pair[1].count = 0;  // an odd count's last
        cameraRays += traceCameraPacketPair(scene, rays, job, pair, hits, &tails);
        for (int half = 0; half < 2 && pair[half].count > 0; ++half) {
          const auto sample = static_cast<std::uint32_t>(pair[half].sample);
          std::array<std::uint32_t, kPacketSize> sampleSeeds{};
          for (int lane = 0; lane < samples.count; ++lane)
            sampleSeeds[lane] = hashU32(samples.pixelSeeds[lane] + sample);
          retraced += static_cast<std::uint64_t>(hits[half].retraced);
          occlusionRays += shadePacket(scene, hits[half], job.shading, sampleSeeds, colours);
          for (int lane = 0; lane < kPacketSize; ++lane) {
            mean.red[lane] += colours.red[lane];
            mean.green[lane] += colours.green[lane];
            mean.blue[lane] += colours.blue[lane];
            mean.alpha[lane] += colours.alpha[lane];
          }
        }
      }
      for (int lane = 0; lane < kPacketSize; ++lane) {
        mean.red[lane] *= scale, mean.green[lane] *= scale;
        mean.blue[lane] *= scale, mean.alpha[lane] *= scale;
      }
      storePixels(mean, samples, image);
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
      const int x0 = (t % across) * job.tileSize, y0 = (t / across) * job.tileSize;
      if (job.samplesPerPixel == 1)
        renderTileSingleSample(scene, rays, job, x0, y0, image, counters);
      else
        renderTileSupersampled(scene, rays, job, x0, y0, image, counters);
      progress.advance();
    }
  });
}

}  // namespace confvis::embree
