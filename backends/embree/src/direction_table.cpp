#include "direction_table.hpp"

#include <optional>

#include <tbb/parallel_for.h>

#include "tail_lattice.hpp"

namespace confvis::embree {

DirectionTable::DirectionTable(const WallMapGrid& grid, const TileJob& job)
    : DirectionTable(
          job,
          [&grid](const float* px, const float* py, int count, float* run) {
            for (int lane = 0; lane < count; ++lane) {
              const WallMapGrid::Sample s = grid.at(px[lane], py[lane]);
              if (!(s.alpha >= 0.5f)) continue;  // unlit: stays zero
              run[lane] = s.direction.x;
              run[kPacketSize + lane] = s.direction.y;
              run[2 * kPacketSize + lane] = s.direction.z;
            }
            return 0.0f;
          },
          false) {}

DirectionTable::DirectionTable(const TileJob& job, const CameraRays& exactRays)
    : DirectionTable(job, PacketSampler{}, true, &exactRays) {}

DirectionTable::DirectionTable(const TileJob& job, const PacketSampler& sampler, bool withOrigins)
    : DirectionTable(job, sampler, withOrigins, nullptr) {}

DirectionTable::DirectionTable(const TileJob& job, const PacketSampler& sampler, bool withOrigins,
                               const CameraRays* exactRays)
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
  fill(job, sampler, exactRays);
}

void DirectionTable::fill(const TileJob& job, const PacketSampler& sampler,
                          const CameraRays* exactRays) {
  // Tiles in parallel, each packet from the sampler straight into its run.
  const int tiles = static_cast<int>(tileFirstPacket_.size());
  tbb::parallel_for(0, tiles, [&](int tile) {
    const int x0 = (tile % tilesAcross_) * tileSize_, y0 = (tile / tilesAcross_) * tileSize_;
    const int x1 = std::min(x0 + tileSize_, width_), y1 = std::min(y0 + tileSize_, height_);
    std::optional<TailLattice> tails;
    if (exactRays) tails.emplace(*exactRays, job, x0, y0, x1, y1);
    for (int sample = 0; sample < samplesPerPixel_; ++sample)
      for (int y = y0; y < y1; y += kBlockRows)
        for (int x = x0; x < x1; x += kBlockColumns) {
          PacketSamples samples = blockAt(x, y, x1, y1);
          samples.sample = sample;
          for (int lane = 0; lane < samples.count; ++lane)
            samples.pixelSeeds[static_cast<std::size_t>(lane)] =
                pixelSeed(job, samples.laneX(lane), samples.laneY(lane));
          std::array<float, kPacketSize> px, py;
          packetPositions(job, samples, px, py);
          const std::size_t packet = packetIndex(x, y, sample);
          float* run = &components_[stride() * packet];
          std::array<float, kPacketSize> laneReach;
          const float reach = tails ? tails->tails(samples, px.data(), py.data(), run,
                                                   laneReach.data())
                                    : sampler(px.data(), py.data(), samples.count, run);
          if (withOrigins_) reach_[packet] = reach;
        }
  });
}

}  // namespace confvis::embree
