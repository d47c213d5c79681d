// The backend's per-map caches (wall grids, direction tables) follow the maps in use: a walk
// that swaps in a new map every few seconds keeps the memory of the last few maps, not of every
// map it ever rendered (tools/soak/walk_soak.py found +0.7 MB per re-bake before).
#include <gtest/gtest.h>

#include <algorithm>

#include "confvis/backends/analytic_maps.hpp"
#include "render_test_support.hpp"

namespace confvis {
namespace {

const EmbreeFrameStats& stats(const RenderResult& result) { return result.stats.embree.value(); }

TEST(EmbreeMapCache, AWalkThroughManyMapsHoldsTheTablesOfTheRecentOnesOnly) {
  const DisplayConfig config = test::shippedConfig("cave5");
  EmbreeBackend backend;  // its own caches
  backend.setScene(builtinScene("checker-sphere"));
  RenderSettings settings;
  settings.mode = RenderMode::Conformal;
  settings.resolutionScale = test::scaleFor(16);
  std::uint64_t oneMapBytes = 0, mostBytes = 0, mostGrids = 0;
  const int maps = 40;
  for (int m = 0; m < maps; ++m) {  // each map for 3 frames, as a walk re-baking often would
    const RetargetMap map = ceilinglessDilationMap(1.2 + 0.01 * m, 16);
    for (int frame = 0; frame < 3; ++frame) {
      const RenderResult result = backend.render(config, &map, settings);
      if (m == 0 && frame == 2) oneMapBytes = stats(result).cachedDirectionTableBytes;
      mostBytes = std::max(mostBytes, stats(result).cachedDirectionTableBytes);
      mostGrids = std::max(mostGrids, stats(result).cachedWallGrids);
    }
  }
  ASSERT_EQ(oneMapBytes, 5u * 16 * 16 * 3 * sizeof(float))
      << "one table of directions per wall after the second frame";
  // Idle after 8 renders: at most the maps of the last 4 (3 frames each) hold anything.
  EXPECT_LE(mostBytes, 4 * oneMapBytes);
  EXPECT_LE(mostGrids, 4u * 5);
  EXPECT_LT(mostGrids, static_cast<std::uint64_t>(maps) * 5) << "the bound must bite";
}

TEST(EmbreeMapCache, MapsRenderedInTurnKeepTheirTables) {
  const DisplayConfig config = test::shippedConfig("cave5");
  EmbreeBackend backend;
  backend.setScene(builtinScene("checker-sphere"));
  RenderSettings settings;
  settings.mode = RenderMode::Conformal;
  settings.resolutionScale = test::scaleFor(16);
  const RetargetMap a = ceilinglessDilationMap(1.3, 16), b = ceilinglessDilationMap(1.5, 16);
  for (int frame = 0; frame < 12; ++frame) {  // a, b, a, b, ...: neither is ever idle long
    const RenderResult ra = backend.render(config, &a, settings);
    const RenderResult rb = backend.render(config, &b, settings);
    if (frame >= 1) {  // from the second render of each on, its tables are read
      EXPECT_EQ(stats(ra).directionTableSamples, 5u * 16 * 16) << frame;
      EXPECT_EQ(stats(rb).directionTableSamples, 5u * 16 * 16) << frame;
    }
  }
}

}  // namespace
}  // namespace confvis
