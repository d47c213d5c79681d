#pragma once
// The conformal centre-eye directions of one image, one per camera sample: F(dir(p)) at every
// sample position the tile renderer draws, read once from the WallMapGrid and kept across
// frames, so a conformal frame does no map lookup at all (only a rotation by the virtual
// camera, as a plain frame does). Unlit samples hold the zero vector.
//
// Stored in the order the tile renderer reads it: tile by tile, within a tile sample by sample,
// then row by row. A frame streams the table once (12 bytes a sample, far beyond the caches at
// full resolution), so each tile reads one contiguous block instead of one short run per row.
#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "confvis/backends/wall_map_grid.hpp"
#include "tile_renderer.hpp"

namespace confvis::embree {

class DirectionTable {
 public:
  // Samples job.width x job.height pixels x job.samplesPerPixel at samplePosition(job, ...),
  // in tiles of job.tileSize.
  DirectionTable(const WallMapGrid& grid, const TileJob& job);

  // Unnormalised F (as WallMapGrid::at returns it), or zero where the map is unlit, of sample
  // `sample` of pixel (x, y); the pixels to its right in the same tile follow it directly.
  const glm::vec3* at(int x, int y, int sample) const { return &directions_[index(x, y, sample)]; }
  std::size_t sampleCount() const { return directions_.size(); }

 private:
  std::size_t index(int x, int y, int sample) const {
    const int x0 = x - x % tileSize_, y0 = y - y % tileSize_;
    const auto tileWidth = static_cast<std::size_t>(std::min(tileSize_, width_ - x0));
    const auto tileHeight = static_cast<std::size_t>(std::min(tileSize_, height_ - y0));
    // Every tile above this tile's row, then those to its left in the row.
    const std::size_t tileStart = static_cast<std::size_t>(y0) * static_cast<std::size_t>(width_) +
                                  static_cast<std::size_t>(x0) * tileHeight;
    return tileStart * static_cast<std::size_t>(samplesPerPixel_) +
           (static_cast<std::size_t>(sample) * tileHeight + static_cast<std::size_t>(y - y0)) *
               tileWidth +
           static_cast<std::size_t>(x - x0);
  }

  int width_ = 0, height_ = 0, samplesPerPixel_ = 1, tileSize_ = 1;
  std::vector<glm::vec3> directions_;
};

}  // namespace confvis::embree
