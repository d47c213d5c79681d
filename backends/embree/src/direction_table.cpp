#include "direction_table.hpp"

#include <tbb/parallel_for.h>

namespace confvis::embree {

DirectionTable::DirectionTable(const WallMapGrid& grid, const TileJob& job)
    : width_(job.width),
      height_(job.height),
      samplesPerPixel_(job.samplesPerPixel),
      tileSize_(job.tileSize) {
  tilesAcross_ = (job.width + tileSize_ - 1) / tileSize_;
  const int tilesDown = (job.height + tileSize_ - 1) / tileSize_;
  std::size_t packets = 0;
  for (int tileY = 0; tileY < tilesDown; ++tileY)
    for (int tileX = 0; tileX < tilesAcross_; ++tileX) {
      tileFirstPacket_.push_back(packets);
      const int tileWidth = std::min(tileSize_, width_ - tileX * tileSize_);
      const int tileHeight = std::min(tileSize_, height_ - tileY * tileSize_);
      packets += static_cast<std::size_t>((tileWidth + kBlockColumns - 1) / kBlockColumns) *
                 static_cast<std::size_t>((tileHeight + kBlockRows - 1) / kBlockRows) *
                 static_cast<std::size_t>(samplesPerPixel_);
    }
  samples_ = static_cast<std::size_t>(job.width) * static_cast<std::size_t>(job.height) *
             static_cast<std::size_t>(job.samplesPerPixel);
  components_.assign(3 * kPacketSize * packets, 0.0f);
  tbb::parallel_for(0, job.height, [&](int y) {
    for (int x = 0; x < job.width; ++x)
      for (int sample = 0; sample < job.samplesPerPixel; ++sample) {
        const glm::dvec2 p = samplePosition(job, x, y, sample);
        const WallMapGrid::Sample s = grid.at(static_cast<float>(p.x), static_cast<float>(p.y));
        if (!(s.alpha >= 0.5f)) continue;  // unlit: stays zero
        float* run = &components_[3 * kPacketSize * packetIndex(x, y, sample)];
        const int lane = laneOf(x, y);
        run[lane] = s.direction.x;
        run[kPacketSize + lane] = s.direction.y;
        run[2 * kPacketSize + lane] = s.direction.z;
      }
  });
}

}  // namespace confvis::embree
