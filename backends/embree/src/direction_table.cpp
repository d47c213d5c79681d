#include "direction_table.hpp"

#include <tbb/parallel_for.h>

namespace confvis::embree {

DirectionTable::DirectionTable(const WallMapGrid& grid, const TileJob& job)
    : width_(job.width), samplesPerPixel_(job.samplesPerPixel) {
  directions_.resize(static_cast<std::size_t>(job.width) * static_cast<std::size_t>(job.height) *
                     static_cast<std::size_t>(job.samplesPerPixel));
  tbb::parallel_for(0, job.height, [&](int y) {
    for (int x = 0; x < job.width; ++x)
      for (int sample = 0; sample < job.samplesPerPixel; ++sample) {
        const glm::dvec2 p = samplePosition(job, x, y, sample);
        const WallMapGrid::Sample s = grid.at(static_cast<float>(p.x), static_cast<float>(p.y));
        directions_[(static_cast<std::size_t>(y) * width_ + static_cast<std::size_t>(x)) *
                        static_cast<std::size_t>(samplesPerPixel_) +
                    static_cast<std::size_t>(sample)] =
            s.alpha >= 0.5f ? s.direction : glm::vec3(0.0f);
      }
  });
}

}  // namespace confvis::embree
