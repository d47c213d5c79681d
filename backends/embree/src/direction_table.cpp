#include "direction_table.hpp"

#include <tbb/parallel_for.h>

namespace confvis::embree {

DirectionTable::DirectionTable(const WallMapGrid& grid, const TileJob& job)
    : width_(job.width),
      height_(job.height),
      samplesPerPixel_(job.samplesPerPixel),
      tileSize_(job.tileSize) {
  directions_.resize(static_cast<std::size_t>(job.width) * static_cast<std::size_t>(job.height) *
                     static_cast<std::size_t>(job.samplesPerPixel));
  tbb::parallel_for(0, job.height, [&](int y) {
    for (int x = 0; x < job.width; ++x)
      for (int sample = 0; sample < job.samplesPerPixel; ++sample) {
        const glm::dvec2 p = samplePosition(job, x, y, sample);
        const WallMapGrid::Sample s = grid.at(static_cast<float>(p.x), static_cast<float>(p.y));
        directions_[index(x, y, sample)] = s.alpha >= 0.5f ? s.direction : glm::vec3(0.0f);
      }
  });
}

}  // namespace confvis::embree
