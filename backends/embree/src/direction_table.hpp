#pragma once
// The conformal centre-eye directions of one image, one per camera sample: F(dir(p)) at every
// sample position the tile renderer draws, read once from the WallMapGrid and kept across
// frames, so a conformal frame does no map lookup at all (only a rotation by the virtual
// camera, as a plain frame does). Unlit samples hold the zero vector.
//
// Stored in the order the tile renderer reads it: tile by tile, within a tile sample by sample,
// then its packets (blocks of 4 x 2 pixels, PacketSamples) row of blocks by row of blocks, each
// as structure of arrays: 8 x, 8 y, 8 z (lanes in PacketSamples' order; zeros past the block's
// pixels inside the tile). A frame streams the table once (12 bytes a sample, far beyond the
// caches at full resolution), so each tile reads one contiguous block, and a packet loads its
// three components as vectors.
#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "confvis/backends/wall_map_grid.hpp"
#include "camera_packet.hpp"
#include "packet_tracer.hpp"
#include "tile_renderer.hpp"

namespace confvis::embree {

class DirectionTable {
 public:
  // Samples job.width x job.height pixels x job.samplesPerPixel at samplePosition(job, ...),
  // in tiles of job.tileSize.
  DirectionTable(const WallMapGrid& grid, const TileJob& job);

  // The packet of sample `sample` of the block whose top-left pixel is (x, y) (a tile's corner
  // plus multiples of the block size): unnormalised F (as WallMapGrid::at returns it), or zero
  // where the map is unlit or past the tile, x components at [0, 8), y at [8, 16), z at [16, 24).
  const float* packet(int x, int y, int sample) const {
    return &components_[3 * kPacketSize * packetIndex(x, y, sample)];
  }
  std::size_t sampleCount() const { return samples_; }

 private:
  // The packet holding sample `sample` of pixel (x, y), and the pixel's lane in it.
  std::size_t packetIndex(int x, int y, int sample) const {
    const int tileX = x / tileSize_, tileY = y / tileSize_;
    const int x0 = tileX * tileSize_, y0 = tileY * tileSize_;
    const int tileWidth = std::min(tileSize_, width_ - x0);
    const int tileHeight = std::min(tileSize_, height_ - y0);
    const int blocksAcross = (tileWidth + kBlockColumns - 1) / kBlockColumns;
    const int blocksDown = (tileHeight + kBlockRows - 1) / kBlockRows;
    const std::size_t tile = static_cast<std::size_t>(tileY) * tilesAcross_ + tileX;
    return tileFirstPacket_[tile] +
           static_cast<std::size_t>((sample * blocksDown + (y - y0) / kBlockRows) * blocksAcross +
                                    (x - x0) / kBlockColumns);
  }
  int laneOf(int x, int y) const {
    const int x0 = x - x % tileSize_, y0 = y - y % tileSize_;
    const PacketSamples block =
        blockAt(x0 + (x - x0) / kBlockColumns * kBlockColumns,
                y0 + (y - y0) / kBlockRows * kBlockRows, std::min(x0 + tileSize_, width_),
                std::min(y0 + tileSize_, height_));
    return (y - block.y) * block.columns + (x - block.x);
  }

  int width_ = 0, height_ = 0, samplesPerPixel_ = 1, tileSize_ = 1, tilesAcross_ = 1;
  std::vector<std::size_t> tileFirstPacket_;  // per tile (row-major), its first packet
  std::size_t samples_ = 0;
  std::vector<float> components_;
};

}  // namespace confvis::embree
