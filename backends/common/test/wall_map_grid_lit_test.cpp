// WallMapGrid::litThroughout: where it says a box of the wall is lit throughout, at() gives
// alpha >= 0.5 at every position in it (the exact stereo tails then skip the per-sample alpha,
// issue 23). The 6-sided CAVE under the ceilingless map has an unlit ceiling, so boxes on both
// sides of the edge between lit and unlit are met.
#include <gtest/gtest.h>

#include <random>

#include "confvis/backends/analytic_maps.hpp"
#include "confvis/backends/wall_map_grid.hpp"

namespace confvis {
namespace {

TEST(WallMapGridLit, LitThroughoutBoxesAreLitAtEveryPosition) {
  const DisplayConfig config =
      loadDisplayConfig(std::string(CONFVIS_SOURCE_DIR) + "/configs/cave6.json");
  const RetargetMap map = ceilinglessDilationMap(1.5, 64);
  const ConformalWarp warp(map);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  int litBoxes = 0, boxesWithUnlitPositions = 0;
  for (const Wall& wall : config.walls) {
    SCOPED_TRACE(wall.name);
    const WallMapGrid grid(warp, wall, WallMapGrid::spacingFor(wall, config.reference, 64, 0.25));
    for (int k = 0; k < 600; ++k) {
      const float size = 4.0f + 60.0f * unit(rng);  // a 4 x 4-pixel cell at 1 to 1/15 scale
      const float x0 = unit(rng) * (static_cast<float>(wall.width) - size);
      const float y0 = unit(rng) * (static_cast<float>(wall.height) - size);
      bool unlitSomewhere = false;
      for (int j = 0; j <= 8; ++j)
        for (int i = 0; i <= 8; ++i)
          unlitSomewhere = unlitSomewhere ||
                           !(grid.at(x0 + size * i / 8.0f, y0 + size * j / 8.0f).alpha >= 0.5f);
      const bool lit = grid.litThroughout(x0, y0, x0 + size, y0 + size);
      EXPECT_FALSE(lit && unlitSomewhere) << "box at " << x0 << ", " << y0 << " size " << size;
      litBoxes += lit ? 1 : 0;
      boxesWithUnlitPositions += unlitSomewhere ? 1 : 0;
    }
  }
  // Neither side vacuous.
  EXPECT_GT(litBoxes, 1000);
  EXPECT_GT(boxesWithUnlitPositions, 100);
}

}  // namespace
}  // namespace confvis
