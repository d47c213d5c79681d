// Every triangle drawn (issue 23): in conformal mode a triangle that spans a large angle seen from
// the warp's centre bends far more than one tessellation patch can follow, and the pre-pass's
// drop rules (made for pieces torn across the source's cut) threw such triangles away: a two-
// triangle quad 0.5 m in front of the viewer mostly vanished, and so did a ground plane under the
// viewer. The Vulkan backend splits such triangles before the warp; Embree (rays, no tessellation)
// is the reference.
#include <gtest/gtest.h>

#include "confvis/backends/analytic_maps.hpp"
#include "confvis/backends/embree/embree_backend.hpp"
#include "vulkan_test_scenes.hpp"
#include "vulkan_test_support.hpp"

namespace confvis {
namespace {

constexpr float kTolerance = 0.1f;  // per channel, linear colour
// Share of a wall's pixels over the tolerance: checker edges that the raster and the rays place
// on either side, and the tessellation's half-pixel error bound.
constexpr double kBudget = 0.03;

// A textured quad 0.5 m in front of the viewer, 20 m wide: it fills the front half of the view.
Scene nearQuad(const glm::vec3& c) {
  Scene scene;
  scene.name = "near quad";
  const int texture = test::addTexture(scene, test::checkerTexture({0.9f, 0.8f, 0.2f}, 8));
  const int material = test::addMaterial(scene, "near quad", glm::vec4(1.0f), texture);
  scene.meshes.push_back(
      test::facingQuad("near quad", c, {0.0f, 0.0f, -1.0f}, 0.5f, 10.0f, material, 40.0f));
  return scene;
}

// A textured ground plane 1.2 m under the viewer, 100 m across, squares of 0.5 m.
Scene groundPlane(const glm::vec3& c) {
  Scene scene;
  scene.name = "ground plane";
  const int texture = test::addTexture(scene, test::checkerTexture({0.3f, 0.7f, 0.9f}, 8));
  const int material = test::addMaterial(scene, "ground", glm::vec4(1.0f), texture);
  scene.meshes.push_back(
      test::facingQuad("ground", c, {0.0f, -1.0f, 0.0f}, 1.2f, 50.0f, material, 25.0f));
  return scene;
}

RenderSettings conformal(const DisplayConfig& config, std::vector<Eye> eyes) {
  RenderSettings settings;
  settings.mode = RenderMode::Conformal;
  settings.eyes = std::move(eyes);
  settings.head.position = config.reference;
  settings.camera.position = config.reference;
  settings.resolutionScale = test::scaleFor(config, 64);
  return settings;
}

struct Comparison {
  double worst = 0.0;
  std::string where;
};

// Worst wall-and-eye image of `vulkan` against Embree's render of the same scene.
Comparison compareWithEmbree(const Scene& scene, const DisplayConfig& config, const RetargetMap& map,
                             const RenderSettings& settings, const RenderResult& vulkan) {
  EmbreeBackend embree;
  embree.setScene(scene);
  const RenderResult reference = embree.render(config, &map, settings);
  Comparison worst;
  for (const WallImage& image : reference.images) {
    const test::PixelComparison c = test::comparePixels(
        test::imageOf(vulkan, image.wall, image.eye).image, image.image, kTolerance);
    if (c.badFraction() >= worst.worst)
      worst = {c.badFraction(), image.wall + " eye " + std::to_string(int(image.eye))};
  }
  return worst;
}

RenderResult vulkanRender(const Scene& scene, const DisplayConfig& config, const RetargetMap& map,
                          const RenderSettings& settings, VulkanOptions options = {}) {
  test::ValidatedBackend backend(options);
  backend->setScene(scene);
  RenderResult result = backend->render(config, &map, settings);
  test::expectNoValidationMessages(backend);
  return result;
}

// Within the budget of Embree's render with the split, and (the comparison can fail) far over
// it with the triangles drawn whole.
void expectDrawnAsEmbreeDraws(const Scene& scene, std::vector<Eye> eyes) {
  const DisplayConfig config = test::loadConfig("cave5");
  const RetargetMap map = ceilinglessDilationMap(1.5, 64, config.reference);
  const RenderSettings settings = conformal(config, std::move(eyes));
  const Comparison c =
      compareWithEmbree(scene, config, map, settings, vulkanRender(scene, config, map, settings));
  ::testing::Test::RecordProperty("worst_bad_fraction", std::to_string(c.worst));
  EXPECT_LE(c.worst, kBudget) << c.where;
  VulkanOptions whole;
  whole.splitWideTriangles = false;
  const Comparison unsplit = compareWithEmbree(scene, config, map, settings,
                                               vulkanRender(scene, config, map, settings, whole));
  ::testing::Test::RecordProperty("worst_bad_fraction_unsplit", std::to_string(unsplit.worst));
  EXPECT_GT(unsplit.worst, 3 * kBudget) << unsplit.where;
}

TEST(VulkanLargeTriangles, ANearTwoTriangleQuadIsDrawnAsEmbreeDrawsIt) {
  expectDrawnAsEmbreeDraws(nearQuad(glm::vec3(test::loadConfig("cave5").reference)),
                           {Eye::Center});
}

TEST(VulkanLargeTriangles, ANearTwoTriangleQuadIsDrawnForBothEyes) {
  expectDrawnAsEmbreeDraws(nearQuad(glm::vec3(test::loadConfig("cave5").reference)),
                           {Eye::Left, Eye::Right});
}

TEST(VulkanLargeTriangles, AGroundPlaneUnderTheViewerIsDrawnAsEmbreeDrawsIt) {
  expectDrawnAsEmbreeDraws(groundPlane(glm::vec3(test::loadConfig("cave5").reference)),
                           {Eye::Center, Eye::Left, Eye::Right});
}

}  // namespace
}  // namespace confvis
