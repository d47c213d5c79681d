#include "direction_table.hpp"

#include <tbb/parallel_for.h>

namespace confvis::embree {

DirectionTable::DirectionTable(const WallMapGrid& grid, const TileJob& job)
    : DirectionTable(
          job,
          [&grid](double px, double py, glm::vec3& direction, glm::vec3&, float&) {
            const WallMapGrid::Sample s = grid.at(static_cast<float>(px), static_cast<float>(py));
            direction = s.direction;
            return s.alpha >= 0.5f;
          },
          false) {}

DirectionTable::DirectionTable(const TileJob& job, const Sampler& sampler, bool withOrigins)
    : width_(job.width),
      height_(job.height),
      samplesPerPixel_(job.samplesPerPixel),
      tileSize_(job.tileSize),
      withOrigins_(withOrigins) {
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
  components_.assign(stride() * packets, 0.0f);
  if (withOrigins_) reach_.assign(packets, 0.0f);
  fill(job, sampler);
}

void DirectionTable::fill(const TileJob& job, const Sampler& sampler) {
  // Rows of tiles in parallel: a packet's lanes (and so its reach) belong to one task.
  const int tileRows = (job.height + tileSize_ - 1) / tileSize_;
  tbb::parallel_for(0, tileRows, [&](int tileRow) {
    const int yEnd = std::min(job.height, (tileRow + 1) * tileSize_);
    for (int y = tileRow * tileSize_; y < yEnd; ++y)
      for (int x = 0; x < job.width; ++x)
        for (int sample = 0; sample < job.samplesPerPixel; ++sample) {
          const glm::dvec2 p = samplePosition(job, x, y, sample);
          glm::vec3 direction(0.0f), origin(0.0f);
          float reach = 0.0f;
          if (!sampler(p.x, p.y, direction, origin, reach)) continue;  // unlit: stays zero
          const std::size_t packet = packetIndex(x, y, sample);
          float* run = &components_[stride() * packet];
          const int lane = laneOf(x, y);
          run[lane] = direction.x;
          run[kPacketSize + lane] = direction.y;
          run[2 * kPacketSize + lane] = direction.z;
          if (!withOrigins_) continue;
          run[3 * kPacketSize + lane] = origin.x;
          run[4 * kPacketSize + lane] = origin.y;
          run[5 * kPacketSize + lane] = origin.z;
          reach_[packet] = std::max(reach_[packet], reach);
        }
  });
}

}  // namespace confvis::embree
