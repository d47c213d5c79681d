#pragma once
// The conformal centre-eye directions of one image, one per camera sample: F(dir(p)) at every
// sample position the tile renderer draws, read once from the WallMapGrid and kept across
// frames, so a conformal frame does no map lookup at all (only a rotation by the virtual
// camera, as a plain frame does). Unlit samples hold the zero vector.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "confvis/backends/wall_map_grid.hpp"
#include "tile_renderer.hpp"

namespace confvis::embree {

class DirectionTable {
 public:
  // Samples job.width x job.height pixels x job.samplesPerPixel at samplePosition(job, ...).
  DirectionTable(const WallMapGrid& grid, const TileJob& job);

  // Unnormalised F (as WallMapGrid::at returns it), or zero where the map is unlit.
  const glm::vec3& at(int x, int y, int sample) const {
    return directions_[(static_cast<std::size_t>(y) * width_ + static_cast<std::size_t>(x)) *
                           static_cast<std::size_t>(samplesPerPixel_) +
                       static_cast<std::size_t>(sample)];
  }
  std::size_t sampleCount() const { return directions_.size(); }

 private:
  int width_ = 0, samplesPerPixel_ = 1;
  std::vector<glm::vec3> directions_;
};

}  // namespace confvis::embree
