// Depth at any scale (issue 23): the same display, head, camera, map and scene scaled together by
// 1e-3 (a CAVE of millimetres) and 1e3 (kilometres) must render the same images, since every
// ray, warp and shading term scales with them. Embree (rays from t = 0 to infinity) is the
// reference. The scene stacks posters 2 cm in front of the walls of a 12 m room: a depth buffer
// with a fixed near plane of 1 cm clipped the millimetre room away and z-fought the posters of the
// kilometre one; reverse-Z with an infinite far plane resolves both.
#include <gtest/gtest.h>

#include "confvis/backends/analytic_maps.hpp"
#include "confvis/backends/embree/embree_backend.hpp"
#include "vulkan_test_scenes.hpp"
#include "vulkan_test_support.hpp"

namespace confvis {
namespace {

constexpr float kTolerance = 0.1f;  // per channel, linear colour
// Share of a wall's pixels over the tolerance: pixels on an edge that the raster and the rays
// place on either side (measured at scale 1: at most 1.0 % of a wall).
constexpr double kBudget = 0.02;

constexpr float kRoomHalfSize = 6.0f;     // metres from the viewer to each wall of the room
constexpr float kPosterGap = 0.02f;       // posters hang this far in front of the walls
constexpr float kPosterHalfSize = 3.0f;

// The room around the display's reference point c, everything scaled by `scale` about the origin.
Scene posterRoom(const glm::dvec3& c, float scale) {
  Scene scene;
  scene.name = "poster room";
  const int wall = test::addMaterial(scene, "wall", glm::vec4(0.9f, 0.2f, 0.1f, 1.0f));
  const int poster = test::addMaterial(scene, "poster", glm::vec4(0.1f, 0.8f, 0.3f, 1.0f));
  for (int k = 0; k < 6; ++k) {
    glm::vec3 axis(0.0f);
    axis[k / 2] = (k % 2) ? 1.0f : -1.0f;
    scene.meshes.push_back(
        test::facingQuad("wall", glm::vec3(c), axis, kRoomHalfSize, kRoomHalfSize, wall));
    scene.meshes.push_back(test::facingQuad("poster", glm::vec3(c), axis,
                                            kRoomHalfSize - kPosterGap, kPosterHalfSize, poster));
  }
  return test::scaledScene(scene, scale);
}

struct ScaledCase {
  DisplayConfig config;
  RetargetMap map;
  Scene scene;
  RenderSettings settings;
};

// The 5-sided CAVE with its analytic ceilingless map, the head 20 cm off centre (so the stereo
// eyes and the warp's centre all differ), at `scale`.
ScaledCase scaledCase(double scale, RenderMode mode, std::vector<Eye> eyes) {
  const DisplayConfig unit = test::loadConfig("cave5");
  ScaledCase s{test::scaledDisplay(unit, scale), {}, posterRoom(unit.reference, float(scale)), {}};
  s.map = ceilinglessDilationMap(1.5, 64, s.config.reference);
  s.settings.mode = mode;
  s.settings.eyes = std::move(eyes);
  s.settings.head.position = s.config.reference + scale * glm::dvec3(0.2, -0.1, 0.15);
  s.settings.camera.position = s.config.reference;
  s.settings.resolutionScale = test::scaleFor(unit, 48);
  return s;
}

// Worst share of a wall-and-eye image's pixels off the Embree render of the same case.
double worstBadFraction(const ScaledCase& s, const RenderResult& vulkan) {
  EmbreeBackend embree;
  embree.setScene(s.scene);
  const RenderResult reference = embree.render(s.config, &s.map, s.settings);
  double worst = 0.0;
  for (const WallImage& image : reference.images) {
    const test::PixelComparison c = test::comparePixels(
        test::imageOf(vulkan, image.wall, image.eye).image, image.image, kTolerance);
    worst = std::max(worst, c.badFraction());
  }
  return worst;
}

RenderResult vulkanRender(const ScaledCase& s) {
  test::ValidatedBackend backend;
  backend->setScene(s.scene);
  RenderResult result = backend->render(s.config, &s.map, s.settings);
  test::expectNoValidationMessages(backend);
  return result;
}

void expectMatchesEmbreeAtEveryScale(RenderMode mode, std::vector<Eye> eyes) {
  for (double scale : {1e-3, 1.0, 1e3}) {
    SCOPED_TRACE("scale " + std::to_string(scale));
    const ScaledCase s = scaledCase(scale, mode, eyes);
    const double bad = worstBadFraction(s, vulkanRender(s));
    ::testing::Test::RecordProperty("bad_fraction_at_scale_" + std::to_string(scale), std::to_string(bad));
    EXPECT_LE(bad, kBudget);
  }
}

TEST(VulkanDepthScale, PlainStereoMatchesEmbreeFromMillimetresToKilometres) {
  expectMatchesEmbreeAtEveryScale(RenderMode::Plain, {Eye::Left, Eye::Right});
}

TEST(VulkanDepthScale, ConformalCentreEyeMatchesEmbreeFromMillimetresToKilometres) {
  expectMatchesEmbreeAtEveryScale(RenderMode::Conformal, {Eye::Center});
}

TEST(VulkanDepthScale, ConformalStereoMatchesEmbreeFromMillimetresToKilometres) {
  expectMatchesEmbreeAtEveryScale(RenderMode::Conformal, {Eye::Left, Eye::Right});
}

// The comparison can fail: Embree drawing the room without its posters (what a depth buffer that
// lost them would show) is far over the budget.
TEST(VulkanDepthScale, ARenderWithoutThePostersFailsTheComparison) {
  ScaledCase s = scaledCase(1.0, RenderMode::Plain, {Eye::Left, Eye::Right});
  const RenderResult vulkan = vulkanRender(s);
  std::erase_if(s.scene.meshes, [](const Mesh& mesh) { return mesh.name == "poster"; });
  EXPECT_GT(worstBadFraction(s, vulkan), 5 * kBudget);
}

}  // namespace
}  // namespace confvis
