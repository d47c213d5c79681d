// Image regression on lavapipe: the built-in scenes on the 5-sided CAVE and the tiled wall,
// compared per pixel with goldens in tests/golden/vulkan/ (tolerance plus a bad-pixel budget),
// and deliberately broken renders (swapped eyes, wrong warp, no tessellation) that must fail the
// same comparison.
//
// Goldens are written, never regenerated to pass: CONFVIS_UPDATE_GOLDENS=1 rewrites every file
// (EXR, half float, all walls of a case stacked top to bottom in config order, one file per eye,
// a PNG preview beside each); look at the previews before committing them.
//
// Conformal goldens with real baked maps (MapKind::Baked): the config's map is baked inside the
// test, without the cache (the bake is deterministic), so a change to the bake shows up here too.
#include <gtest/gtest.h>

#include <cstdlib>

#include "confvis/base/exr_io.hpp"
#include "confvis/base/png_io.hpp"
#include "confvis/conformal/bake_display.hpp"
#include "confvis/engine/builtin_scenes.hpp"
#include "vulkan_test_maps.hpp"
#include "vulkan_test_support.hpp"

namespace confvis {
namespace {

namespace fs = std::filesystem;

// A pixel is bad when a channel is off by more than kTolerance; a case passes with at most
// kBudget of its pixels bad (room for rasterization differences between Mesa releases).
constexpr float kTolerance = 0.05f;
constexpr double kBudget = 0.01;

enum class MapKind { None, AzimuthSqueeze, Baked };

// Texels per face of the baked maps: at 64-pixel walls a texel is about a pixel.
constexpr int kBakeResolution = 64;

struct GoldenCase {
  std::string config;
  std::string scene;
  RenderMode mode = RenderMode::Plain;
  MapKind map = MapKind::None;
  std::vector<Eye> eyes{Eye::Center};
  int wallPixels = 64;  // width of the config's first wall in the render

  std::string name() const {
    std::string n = config + "-" + scene + (mode == RenderMode::Plain ? "-plain" : "-conformal");
    if (map == MapKind::AzimuthSqueeze) n += "-squeeze";
    if (map == MapKind::Baked) n += "-baked";
    return n + (eyes.size() > 1 ? "-stereo" : "-mono");
  }
};

// Test names and CTest listings show the case, not its bytes.
void PrintTo(const GoldenCase& c, std::ostream* os) { *os << c.name(); }

std::vector<GoldenCase> goldenCases() {
  std::vector<GoldenCase> cases;
  for (const char* config : {"cave5", "md230x6"})
    for (const std::string& scene : builtinSceneNames()) cases.push_back({config, scene});
  // Stereo at a size where the eyes' disparity (under a pixel at 64 px) shows.
  cases.push_back({"cave5", "checker-tunnel", RenderMode::Plain, MapKind::None,
                   {Eye::Left, Eye::Right}, 128});
  // The conformal path (tessellation, warp, cut handling) under an analytic map with a cut.
  cases.push_back({"cave5", "checker-sphere", RenderMode::Conformal, MapKind::AzimuthSqueeze});
  cases.push_back({"cave5", "checker-tunnel", RenderMode::Conformal, MapKind::AzimuthSqueeze});
  // Real baked maps: the 5-sided CAVE (missing ceiling squeezed in) and the six-wall dome-like
  // md230x6 (seams and corners far from a cube's).
  cases.push_back({"cave5", "checker-sphere", RenderMode::Conformal, MapKind::Baked});
  cases.push_back({"cave5", "checker-tunnel", RenderMode::Conformal, MapKind::Baked});
  cases.push_back({"md230x6", "checker-sphere", RenderMode::Conformal, MapKind::Baked});
  return cases;
}

const char* eyeName(Eye eye) {
  return eye == Eye::Left ? "left" : eye == Eye::Right ? "right" : "center";
}

fs::path goldenPath(const GoldenCase& c, Eye eye) {
  return fs::path(CONFVIS_SOURCE_DIR) / "tests" / "golden" / "vulkan" /
         (c.name() + "-" + eyeName(eye) + ".exr");
}

RetargetMap bakedMap(const DisplayConfig& config) {
  return test::bakeUncached(config, kBakeResolution);
}

std::optional<RetargetMap> mapFor(MapKind kind, const DisplayConfig& config) {
  if (kind == MapKind::AzimuthSqueeze) return test::azimuthSqueezeMap(64);
  if (kind == MapKind::Baked) return bakedMap(config);
  return std::nullopt;
}

RenderResult renderCase(const GoldenCase& c, VulkanOptions options = {},
                        const RetargetMap* mapOverride = nullptr) {
  test::ValidatedBackend vk(options);
  const DisplayConfig config = test::loadConfig(c.config);
  vk->setScene(builtinScene(c.scene));
  const std::optional<RetargetMap> map = mapOverride ? std::nullopt : mapFor(c.map, config);
  RenderSettings settings;
  settings.mode = c.mode;
  settings.eyes = c.eyes;
  settings.resolutionScale = test::scaleFor(config, c.wallPixels);
  RenderResult result =
      vk->render(config, mapOverride ? mapOverride : (map ? &*map : nullptr), settings);
  test::expectNoValidationMessages(vk);
  return result;
}

// All walls of one eye stacked top to bottom (config order), as stored in the golden files.
ImageRGBA stackWalls(const RenderResult& result, Eye eye) {
  std::vector<const ImageRGBA*> walls;
  int width = 0, height = 0;
  for (const WallImage& image : result.images)
    if (image.eye == eye) {
      walls.push_back(&image.image);
      width = std::max(width, image.image.width);
      height += image.image.height;
    }
  ImageRGBA stacked(width, height);
  int top = 0;
  for (const ImageRGBA* wall : walls) {
    for (int y = 0; y < wall->height; ++y)
      std::copy_n(wall->at(0, y), 4 * wall->width, stacked.at(0, top + y));
    top += wall->height;
  }
  return stacked;
}

bool updating() { return std::getenv("CONFVIS_UPDATE_GOLDENS") != nullptr; }

// Compares every eye of `result` with the case's goldens; the worst bad-pixel fraction.
double worstBadFraction(const GoldenCase& c, const RenderResult& result,
                        const std::vector<Eye>& goldenEyes) {
  double worst = 0.0;
  for (std::size_t i = 0; i < c.eyes.size(); ++i) {
    const ImageRGBA golden = readExr(goldenPath(c, goldenEyes[i]));
    const test::PixelComparison cmp =
        test::comparePixels(stackWalls(result, c.eyes[i]), golden, kTolerance);
    worst = std::max(worst, cmp.badFraction());
  }
  return worst;
}

class VulkanGolden : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(VulkanGolden, MatchesTheStoredImages) {
  const GoldenCase& c = GetParam();
  const RenderResult result = renderCase(c);
  if (updating()) {
    for (Eye eye : c.eyes) {
      const ImageRGBA stacked = stackWalls(result, eye);
      writeExr(goldenPath(c, eye), stacked, ExrPixel::Half);
      fs::path preview = goldenPath(c, eye);
      writePng(preview.replace_extension(".png"), stacked);
    }
    GTEST_SKIP() << "golden files of " << c.name() << " rewritten";
  }
  ASSERT_TRUE(fs::exists(goldenPath(c, c.eyes.front())))
      << goldenPath(c, c.eyes.front()) << " missing: run with CONFVIS_UPDATE_GOLDENS=1";
  EXPECT_LE(worstBadFraction(c, result, c.eyes), kBudget) << c.name();
}

INSTANTIATE_TEST_SUITE_P(BuiltinScenes, VulkanGolden, ::testing::ValuesIn(goldenCases()),
                         [](const auto& param) {
                           std::string n = param.param.name();
                           std::replace(n.begin(), n.end(), '-', '_');
                           return n;
                         });

GoldenCase findCase(const std::string& name) {
  for (const GoldenCase& c : goldenCases())
    if (c.name() == name) return c;
  throw std::runtime_error("no golden case " + name);
}

TEST(VulkanGoldenBroken, SwappedEyesFail) {
  if (updating()) GTEST_SKIP();
  const GoldenCase c = findCase("cave5-checker-tunnel-plain-stereo");
  const RenderResult result = renderCase(c);
  EXPECT_LE(worstBadFraction(c, result, {Eye::Left, Eye::Right}), kBudget);
  EXPECT_GT(worstBadFraction(c, result, {Eye::Right, Eye::Left}), kBudget);
}

TEST(VulkanGoldenBroken, ConformalWithTheIdentityPassesThePlainGoldenAndAWrongWarpFails) {
  if (updating()) GTEST_SKIP();
  const GoldenCase plain = findCase("cave5-checker-sphere-plain-mono");
  GoldenCase conformal = plain;
  conformal.mode = RenderMode::Conformal;
  const auto badFraction = [&](const RetargetMap& map) {
    return worstBadFraction(plain, renderCase(conformal, {}, &map), plain.eyes);
  };
  const RetargetMap identity = RetargetMap::identity(64);
  EXPECT_LE(badFraction(identity), kBudget);
  // The classic upload bug: faces in the wrong in-face orientation (here converted twice).
  RetargetMap misoriented = identity;
  misoriented.geom = toVulkanLayout(identity.geom);
  EXPECT_GT(badFraction(misoriented), kBudget);
  // A map a few degrees off.
  EXPECT_GT(badFraction(test::rotationMap(64, 3.0)), kBudget);
}

// Broken warps under the real baked maps: no retargeting at all, and the two cube maps swapped
// (geom used where ray belongs: the inverse map, close to right only where the map is nearly
// the identity).
TEST(VulkanGoldenBroken, BakedMapIdentityAndSwappedMapsFail) {
  if (updating()) GTEST_SKIP();
  for (const char* name :
       {"cave5-checker-sphere-conformal-baked-mono", "md230x6-checker-sphere-conformal-baked-mono"}) {
    const GoldenCase c = findCase(name);
    const RetargetMap baked = bakedMap(test::loadConfig(c.config));
    const RetargetMap identity = RetargetMap::identity(kBakeResolution, baked.reference);
    RetargetMap swapped = baked;
    std::swap(swapped.geom, swapped.ray);
    const double identityBad = worstBadFraction(c, renderCase(c, {}, &identity), c.eyes);
    const double swappedBad = worstBadFraction(c, renderCase(c, {}, &swapped), c.eyes);
    RecordProperty(std::string(name) + "_identity", std::to_string(identityBad));
    RecordProperty(std::string(name) + "_swapped", std::to_string(swappedBad));
    EXPECT_GT(identityBad, kBudget) << name;
    EXPECT_GT(swappedBad, kBudget) << name;
  }
}

TEST(VulkanGoldenBroken, BakedMapWithoutTessellationFails) {
  if (updating()) GTEST_SKIP();
  // The tunnel's long edges bend under the real map where the ceiling is squeezed in.
  const GoldenCase c = findCase("cave5-checker-tunnel-conformal-baked-mono");
  VulkanOptions flat;
  flat.tessellate = false;
  const double bad = worstBadFraction(c, renderCase(c, flat), c.eyes);
  RecordProperty("bad_fraction", std::to_string(bad));
  EXPECT_GT(bad, kBudget);
}

TEST(VulkanGoldenBroken, NoTessellationFails) {
  if (updating()) GTEST_SKIP();
  // The tunnel's 1 m quads bend visibly; the checker-sphere's 3-degree triangles hardly do at
  // 64 pixels a wall, so skipping its tessellation is (rightly) within the budget.
  const GoldenCase c = findCase("cave5-checker-tunnel-conformal-squeeze-mono");
  VulkanOptions flat;
  flat.tessellate = false;
  flat.splitWideTriangles = false;  // drawn whole: the split alone bends the quads nearly right
  EXPECT_GT(worstBadFraction(c, renderCase(c, flat), c.eyes), kBudget);
}

}  // namespace
}  // namespace confvis
