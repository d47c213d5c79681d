// WallMapGrid: the retarget map sampled on a grid over each wall, against direct map lookups
// and the exact (analytic) map.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "confvis/backends/analytic_maps.hpp"
#include "confvis/backends/wall_map_grid.hpp"

namespace confvis {
namespace {

// The grid interpolates the map's lookups: in a wall's interior it reproduces them, and the
// exact map, to 1-2 % of a full-resolution pixel (~1e-3 rad at a CAVE wall's centre). Within half
// a map texel of a cube face edge the lookup itself is rougher (sampleBilinear fetches the
// neighbouring face's nearest texel: up to ~1e-3 rad off the exact map there) and the grid
// follows it to 0.2 pixel.
TEST(WallMapGrid, MatchesDirectMapLookupsFarBelowAPixel) {
  const DisplayConfig config = loadDisplayConfig(std::string(CONFVIS_SOURCE_DIR) + "/configs/cave5.json");
  const double lambda = 1.5;
  const RetargetMap map = ceilinglessDilationMap(lambda, 256);
  const ConformalWarp warp(map);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto angle = [](const glm::dvec3& a, const glm::dvec3& b) {
    return std::acos(std::min(1.0, glm::dot(glm::normalize(a), glm::normalize(b))));
  };
  for (const Wall& wall : config.walls) {
    SCOPED_TRACE(wall.name);
    const double spacing = WallMapGrid::spacingFor(wall, config.reference, 256, 1.0);
    EXPECT_GT(spacing, 1.0);  // coarser than the full-resolution pixels...
    EXPECT_LT(spacing, 4.0);  // ...but within half a texel (7.5 px)
    const WallMapGrid grid(warp, wall, spacing);
    double interiorWorst = 0, interiorAgainstTruth = 0, worst = 0;
    int litDisagreements = 0;
    for (int k = 0; k < 4000; ++k) {
      const double px = unit(rng) * wall.width, py = unit(rng) * wall.height;
      const glm::dvec3 p = wall.pointAt(px / wall.width, 1.0 - py / wall.height);
      const ConformalWarp::Lookup direct = warp.lookup(p - config.reference);
      const WallMapGrid::Sample s = grid.at(static_cast<float>(px), static_cast<float>(py));
      if ((s.alpha >= 0.5f) != direct.lit) ++litDisagreements;
      const glm::dvec3 got(s.direction);
      const bool interior = std::min({px, py, wall.width - px, wall.height - py}) > 8.0;
      if (interior) interiorWorst = std::max(interiorWorst, angle(got, direct.direction));
      const glm::dvec3 truth = stereographicDilation(glm::normalize(p - config.reference), lambda);
      if (interior) interiorAgainstTruth = std::max(interiorAgainstTruth, angle(got, truth));
      worst = std::max(worst, angle(got, direct.direction));
    }
    EXPECT_LT(interiorWorst, 1e-5);
    EXPECT_LT(interiorAgainstTruth, 2e-5);
    EXPECT_LT(worst, 2e-4);
    EXPECT_EQ(litDisagreements, 0);
  }
}

}  // namespace
}  // namespace confvis
