// Vulkan against Embree along the top rim of the 5-sided CAVE's side walls, centre eye, through
// the real baked map (issue 23, point 5). The missing ceiling is the map's cut: T_geom opens it
// onto the walls' top edges and grows like a square root of the distance next to it, so the
// rasterizer must draw its triangles split along the cut up to the rim, where Embree's rays draw
// a clean edge. Seen in `confvis render --backend vulkan` (cave5, checker-sphere) as black
// saw-tooth cracks along the top rows of the front and left walls.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <string>

#include "../backends/vulkan/test/vulkan_test_support.hpp"
#include "confvis/backends/embree/embree_backend.hpp"
#include "confvis/conformal/bake_display.hpp"
#include "confvis/engine/builtin_scenes.hpp"

namespace confvis {
namespace {

constexpr float kTolerance = 0.1f;  // per channel, linear colour and alpha
constexpr int kWallPixels = 240;
constexpr int kRimRows = 12;  // the top rows of a 240-px wall: the band next to the cut
constexpr std::array<const char*, 4> kSideWalls = {"front", "left", "right", "back"};

ImageRGBA topRows(const ImageRGBA& image, int rows) {
  ImageRGBA rim(image.width, rows);
  std::copy_n(image.pixels.begin(), rim.pixels.size(), rim.pixels.begin());
  return rim;
}

struct RimCase {
  DisplayConfig config = test::loadConfig("cave5");
  Scene scene = builtinScene("checker-sphere");  // its default 12k triangles, as confvis render
  RetargetMap map;
  RenderSettings settings;
  RenderResult embree;

  RimCase() {
    map = test::bakeUncached(config, 128);
    settings.mode = RenderMode::Conformal;
    settings.head.position = config.reference;
    settings.camera.position = config.reference;
    settings.resolutionScale = test::scaleFor(config, kWallPixels);
    EmbreeBackend backend;
    backend.setScene(scene);
    embree = backend.render(config, &map, settings);
  }

  RenderResult vulkan(const VulkanOptions& options = {}) {
    test::ValidatedBackend backend(options);
    backend->setScene(scene);
    RenderResult result = backend->render(config, &map, settings);
    test::expectNoValidationMessages(backend);
    return result;
  }

  // Each side wall's share of its rim rows off Embree's by more than the tolerance (recorded as
  // test properties).
  std::array<double, 4> rimBadFractions(const RenderResult& vulkan, const char* label) {
    std::array<double, 4> fractions{};
    for (std::size_t i = 0; i < kSideWalls.size(); ++i) {
      const char* wall = kSideWalls[i];
      fractions[i] = test::comparePixels(topRows(test::imageOf(vulkan, wall).image, kRimRows),
                                         topRows(test::imageOf(embree, wall).image, kRimRows),
                                         kTolerance)
                         .badFraction();
      ::testing::Test::RecordProperty(std::string(label) + "_" + wall + "_rim_bad_fraction",
                                      std::to_string(fractions[i]));
    }
    return fractions;
  }
};

double mean(const std::array<double, 4>& values) {
  return std::accumulate(values.begin(), values.end(), 0.0) / double(values.size());
}

// The rim is not clean yet (issue 23, point 5, open): what is left lies next to the wall corners
// where the cut ends (its leaves), where Vulkan's pieces end short of the rim and bend their edges
// differently (the middle of the walls matches). Measured at 240-px walls, 128-texel map: 5.7 /
// 4.8 / 4.3 / 1.1 % of the front, left, right and back walls' top 12 rows off Embree (mean
// 4.0 %); 6.2 / 5.0 / 5.9 / 1.2 % while warp.geom drew the pieces the cut tears up to the
// extrapolated limits, not the rim; with the pre-pass's and the geometry shader's limits both
// left short of the rim (VulkanOptions::snapCutToRim = false) 6.6 / 5.2 / 7.4 / 3.2 % (mean
// 5.6 %); with the pieces across the cut left to the geometry shader instead of split along it
// in the pre-pass (splitAlongCut = false) 5.1 / 4.7 / 4.8 / 1.3 % (mean 4.0 %: warp.geom now
// draws them up to the rim too; 6.8 / 7.6 / 7.9 / 4.6 % while it stopped at the extrapolated
// limits). With the geom lookup's quick bilinear test weighed by the footprint's weights (next to
// the cut's ends it let small jumps through: BackendCrossCheckCutEnds) 5.6 / 4.8 / 4.1 / 1.1 %
// (mean 3.9 %), unsplit 5.0 / 4.7 / 4.6 / 1.3 % (mean 3.9 %). The budgets hold today's drawing
// with a little room for lavapipe's thread order and fail the unsnapped one.
constexpr double kWallBudget = 0.059, kMeanBudget = 0.041;

void expectWithinBudgets(const std::array<double, 4>& fractions) {
  for (std::size_t i = 0; i < fractions.size(); ++i)
    EXPECT_LE(fractions[i], kWallBudget) << kSideWalls[i];
  EXPECT_LE(mean(fractions), kMeanBudget);
}

TEST(BackendCrossCheckRim, TopRimOfTheSideWallsMatchesEmbreeThroughTheBakedCave5Map) {
  RimCase rim;
  expectWithinBudgets(rim.rimBadFractions(rim.vulkan(), "vulkan"));
}

// The pieces across the cut left to the geometry shader (VulkanOptions::splitAlongCut = false):
// warp.geom draws each side of a torn piece up to the cut and moves its ends out to the rim
// through the coverage map, as the pre-pass moves its cut vertices, within the same budgets.
TEST(BackendCrossCheckRim, TheGeometryShadersPiecesAcrossTheCutReachTheRimToo) {
  RimCase rim;
  VulkanOptions unsplit;
  unsplit.splitAlongCut = false;
  expectWithinBudgets(rim.rimBadFractions(rim.vulkan(unsplit), "unsplit"));
}

// Deliberately broken: the limits at the cut left where the geom map's extrapolation puts them
// (VulkanOptions::snapCutToRim = false, in the pre-pass and the geometry shader alike), a band
// short of the rim, fail it.
TEST(BackendCrossCheckRim, TheRimWithoutTheSnapToTheRimFailsTheComparison) {
  RimCase rim;
  VulkanOptions unsnapped;
  unsnapped.snapCutToRim = false;
  const std::array<double, 4> fractions =
      rim.rimBadFractions(rim.vulkan(unsnapped), "unsnapped");
  EXPECT_GT(mean(fractions), 1.2 * kMeanBudget);
  EXPECT_GT(*std::max_element(fractions.begin(), fractions.end()), 1.1 * kWallBudget);
}

}  // namespace
}  // namespace confvis
