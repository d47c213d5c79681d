// The once-a-frame warp (VulkanOptions::warpOncePerFrame, warp_capture.hpp): the pre-pass's
// tessellated lists tessellated, warped and split at the cut once, captured by transform
// feedback, and drawn by every wall and eye with its own projection, must draw what each wall's
// own tessellation draws. The captured positions drawn with another wall's projection must fail,
// and so must the capture without its torn pieces' split in compute (captured_cut_split.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>

#include "vulkan_image_checks.hpp"
#include "vulkan_two_frames.hpp"

namespace confvis {
namespace {

// A pixel is bad where some channel differs by more than kTolerance; a wall passes with at most
// kBudget of its pixels bad. The paths differ only where the geometry shader's cut gap differs
// (each wall's own against the walls' smallest in the capture) and in float rounding (on
// lavapipe: not at all, 0 bad pixels; the wrong wall's projection 0.3-2.5 % a wall).
constexpr float kTolerance = 0.05f;
constexpr double kBudget = 0.001;

TEST(VulkanWarpOncePerFrame, DrawsWhatEachWallsOwnTessellationDraws) {
  // Per wall and once a frame (that frame, and the next one with the head moved: the pre-pass
  // and the capture reused); the captured triangles with the next wall's projection.
  const test::TwoFrames two;
  const auto render = [&](bool oncePerFrame, std::uint32_t viewShift = 0,
                          bool splitTornPieces = true) {
    VulkanOptions options;
    options.warpOncePerFrame = oncePerFrame;
    options.capturedViewShiftForTests = viewShift;
    options.splitCapturedTornPiecesForTests = splitTornPieces;
    return two.render(options);
  };
  const auto perWall = render(false);
  const auto once = render(true);
  const RenderResult wrongWall = render(true, 1).first;
  const RenderResult unsplit = render(true, 0, false).first;
  const VulkanConformalStats& counts = perWall.first.stats.vulkan.value().conformalPrepass.value();
  ASSERT_GT(counts.trianglesTessellated, 30u);
  ASSERT_GT(counts.trianglesThroughGeometryShader, 0u);
  // Worst bad fraction of a wall of `result` against `expected`.
  const auto worst = [](const RenderResult& result, const RenderResult& expected) {
    EXPECT_EQ(result.images.size(), expected.images.size());
    double worstBad = 0.0;
    for (std::size_t i = 0; i < result.images.size() && i < expected.images.size(); ++i)
      worstBad = std::max(worstBad, test::comparePixels(result.images[i].image,
                                                        expected.images[i].image, kTolerance)
                                        .badFraction());
    return worstBad;
  };
  // Something was drawn on most walls (the comparison alone would pass two empty renders).
  std::size_t drawnWalls = 0;
  for (const WallImage& image : perWall.first.images)
    drawnWalls += test::drawnPixels(image.image) > image.image.pixelCount() / 4;
  EXPECT_GE(drawnWalls, 6u);
  const double worstOnce = worst(once.first, perWall.first);
  const double worstMoved = worst(once.second, perWall.second);
  const double worstWrong = worst(wrongWall, perWall.first);
  const double worstUnsplit = worst(unsplit, perWall.first);
  EXPECT_LE(worstOnce, kBudget);
  EXPECT_LE(worstMoved, kBudget);
  EXPECT_GT(worstWrong, kBudget) << "the wrong wall's projection passed";
  EXPECT_GT(worstUnsplit, kBudget) << "the capture without its torn pieces' split passed";
  RecordProperty("worst_bad_fraction", std::to_string(std::max(worstOnce, worstMoved)));
  RecordProperty("wrong_wall_worst_bad_fraction", std::to_string(worstWrong));
  RecordProperty("unsplit_worst_bad_fraction", std::to_string(worstUnsplit));
}

}  // namespace
}  // namespace confvis
