#pragma once
// The conformal centre-eye directions of one image, one per camera sample: F(dir(p)) at every
// sample position the tile renderer draws, read once from the WallMapGrid and kept across
// frames, so a conformal frame does no map lookup at all (only a rotation by the virtual
// camera, as a plain frame does). Unlit samples hold the zero vector.
//
// Stored in the order the tile renderer reads it: tile by tile, within a tile sample by sample,
// then row by row, each row's runs of 8 pixels (one packet) as structure of arrays: 8 x, 8 y, 8
// z (zeros past the tile's edge). A frame streams the table once (12 bytes a sample, far beyond
// the caches at full resolution), so each tile reads one contiguous block, and a packet loads its
// three components as vectors.
#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "confvis/backends/wall_map_grid.hpp"
#include "packet_tracer.hpp"
#include "tile_renderer.hpp"

namespace confvis::embree {

class DirectionTable {
 public:
  // Samples job.width x job.height pixels x job.samplesPerPixel at samplePosition(job, ...),
  // in tiles of job.tileSize.
  DirectionTable(const WallMapGrid& grid, const TileJob& job);

  // The packet of sample `sample` of pixels x .. x + 7 of row y (x at a run start: the tile's
  // left edge plus a multiple of 8): unnormalised F (as WallMapGrid::at returns it), or zero
  // where the map is unlit or past the tile, x components at [0, 8), y at [8, 16), z at [16, 24).
  const float* packet(int x, int y, int sample) const {
    return &components_[3 * runStart(x, y, sample)];
  }
  std::size_t sampleCount() const { return samples_; }

 private:
  // Lanes stored for tile columns before x0 (every tile row run padded to 8 lanes).
  std::size_t paddedX(int x0) const {
    const auto tileColumn = static_cast<std::size_t>(x0 / tileSize_);
    return tileColumn * paddedRun(tileSize_);
  }
  static std::size_t paddedRun(int width) {
    return static_cast<std::size_t>((width + kPacketSize - 1) / kPacketSize * kPacketSize);
  }
  // The first lane of the run that holds sample `sample` of pixel (x, y); a run of 8 lanes holds
  // 24 floats from 3 x its first lane on.
  std::size_t runStart(int x, int y, int sample) const {
    const int x0 = x - x % tileSize_, y0 = y - y % tileSize_;
    const std::size_t run = paddedRun(std::min(tileSize_, width_ - x0));
    const auto tileHeight = static_cast<std::size_t>(std::min(tileSize_, height_ - y0));
    // Every tile above this tile's row, then those to its left in the row.
    const std::size_t tileStart =
        static_cast<std::size_t>(y0) * paddedWidth_ + paddedX(x0) * tileHeight;
    const auto column = static_cast<std::size_t>(x - x0);
    return tileStart * static_cast<std::size_t>(samplesPerPixel_) +
           (static_cast<std::size_t>(sample) * tileHeight + static_cast<std::size_t>(y - y0)) *
               run +
           column / kPacketSize * kPacketSize;
  }

  int width_ = 0, height_ = 0, samplesPerPixel_ = 1, tileSize_ = 1;
  std::size_t paddedWidth_ = 0;  // lanes stored per image row
  std::size_t samples_ = 0;
  std::vector<float> components_;
};

}  // namespace confvis::embree
