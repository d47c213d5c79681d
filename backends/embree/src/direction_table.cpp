#include "direction_table.hpp"

#include <tbb/parallel_for.h>

namespace confvis::embree {

DirectionTable::DirectionTable(const WallMapGrid& grid, const TileJob& job)
    : width_(job.width),
      height_(job.height),
      samplesPerPixel_(job.samplesPerPixel),
      tileSize_(job.tileSize) {
  const int lastTile = (job.width - 1) / tileSize_ * tileSize_;
  paddedWidth_ = paddedX(lastTile) + paddedRun(job.width - lastTile);
  samples_ = static_cast<std::size_t>(job.width) * static_cast<std::size_t>(job.height) *
             static_cast<std::size_t>(job.samplesPerPixel);
  components_.assign(3 * paddedWidth_ * static_cast<std::size_t>(job.height) *
                         static_cast<std::size_t>(job.samplesPerPixel),
                     0.0f);
  tbb::parallel_for(0, job.height, [&](int y) {
    for (int x = 0; x < job.width; ++x)
      for (int sample = 0; sample < job.samplesPerPixel; ++sample) {
        const glm::dvec2 p = samplePosition(job, x, y, sample);
        const WallMapGrid::Sample s = grid.at(static_cast<float>(p.x), static_cast<float>(p.y));
        if (!(s.alpha >= 0.5f)) continue;  // unlit: stays zero
        float* run = &components_[3 * runStart(x, y, sample)];
        const int lane = x % tileSize_ % kPacketSize;
        run[lane] = s.direction.x;
        run[kPacketSize + lane] = s.direction.y;
        run[2 * kPacketSize + lane] = s.direction.z;
      }
  });
}

}  // namespace confvis::embree
