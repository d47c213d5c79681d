// The per-wall cull of the pre-pass's flat list (VulkanOptions::cullFlatListPerWall,
// flat_wall_cull.hpp): each wall draws only the flat triangles that may show on it, and must
// draw what the whole list draws, also in the next frame, whose head moved while the pre-pass is
// reused (the cull runs again with the new frusta). A cull against the next wall's frusta must
// fail, and each wall's list must hold fewer triangles than the whole.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <string>
#include <utility>

#include "vulkan_image_checks.hpp"
#include "vulkan_two_frames.hpp"

namespace confvis {
namespace {

// A pixel is bad where some channel differs by more than kTolerance; a wall passes with at most
// kBudget of its pixels bad. The cull drops no triangle that reaches a wall, so only the lists'
// order (atomic appends) could tell, where two triangles tie in depth on a pixel (measured: none).
constexpr float kTolerance = 0.05f;
constexpr double kBudget = 0.0005;

TEST(VulkanFlatWallCull, EachWallDrawsWhatTheWholeFlatListDraws) {
  const test::TwoFrames two;
  const DisplayConfig& config = two.config;
  const auto render = [&](bool cull, bool nextWallsFrusta = false) {
    VulkanOptions options;
    options.cullFlatListPerWall = cull;
    options.cullFlatListAgainstNextWallForTests = nextWallsFrusta;
    return two.render(options);
  };
  const auto whole = render(false);
  const auto culled = render(true);
  const auto wrong = render(true, true);

  // Each wall's list is a part of the flat list: fewer triangles than the whole, none empty.
  for (const auto* result : {&culled.first, &culled.second}) {
    const VulkanConformalStats& counts = result->stats.vulkan.value().conformalPrepass.value();
    ASSERT_EQ(counts.flatTrianglesPerWall.size(), config.walls.size());
    const std::uint64_t flatList = counts.trianglesDrawnFlat;  // the flat list and the pieces
    ASSERT_GT(flatList, 5000u);
    for (std::uint64_t wallTriangles : counts.flatTrianglesPerWall) {
      EXPECT_GT(wallTriangles, 0u);
      EXPECT_LT(wallTriangles, flatList * 3 / 4);
    }
    const std::uint64_t all = std::accumulate(counts.flatTrianglesPerWall.begin(),
                                              counts.flatTrianglesPerWall.end(), std::uint64_t{0});
    RecordProperty("wall_lists_over_whole", std::to_string(double(all) / double(flatList)));
  }
  EXPECT_TRUE(whole.first.stats.vulkan.value().conformalPrepass.value()
                  .flatTrianglesPerWall.empty());

  const auto worst = [](const RenderResult& result, const RenderResult& expected) {
    EXPECT_EQ(result.images.size(), expected.images.size());
    double worstBad = 0.0;
    for (std::size_t i = 0; i < result.images.size() && i < expected.images.size(); ++i)
      worstBad = std::max(worstBad, test::comparePixels(result.images[i].image,
                                                        expected.images[i].image, kTolerance)
                                        .badFraction());
    return worstBad;
  };
  std::size_t drawnWalls = 0;  // the comparison alone would pass two empty renders
  for (const WallImage& image : whole.first.images)
    drawnWalls += test::drawnPixels(image.image) > image.image.pixelCount() / 4;
  EXPECT_GE(drawnWalls, 6u);
  const double worstCulled = worst(culled.first, whole.first);
  const double worstMoved = worst(culled.second, whole.second);
  const double worstWrong = worst(wrong.first, whole.first);
  EXPECT_LE(worstCulled, kBudget);
  EXPECT_LE(worstMoved, kBudget);
  EXPECT_GT(worstWrong, kBudget) << "the cull against the next wall's frusta passed";
  RecordProperty("worst_bad_fraction", std::to_string(std::max(worstCulled, worstMoved)));
  RecordProperty("wrong_frusta_worst_bad_fraction", std::to_string(worstWrong));
}

}  // namespace
}  // namespace confvis
