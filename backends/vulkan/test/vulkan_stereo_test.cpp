// Stereo: each eye gets its own off-axis projection, so a near object shifts between the eyes by
// the closed-form disparity; with VK_KHR_multiview both eyes of a wall are drawn in one pass.
#include <gtest/gtest.h>

#include "confvis/engine/builtin_scenes.hpp"
#include "vulkan_test_support.hpp"

namespace confvis {
namespace {

using test::imageOf;

constexpr double kSquareDistance = 0.25;  // metres in front of the viewer
constexpr double kSquareHalfSize = 0.03;

// A small yellow square hanging close to the viewer, well inside both eyes' view of the front
// wall (so no triangle needs clipping), optionally in front of the checker-sphere.
Scene nearSquare(bool withBackdrop) {
  Scene scene;
  scene.name = "near square";
  if (withBackdrop) scene = builtinScene("checker-sphere");
  scene.materials.push_back({"yellow", glm::vec4(1.0f, 1.0f, 0.0f, 1.0f), -1});
  Mesh square;
  square.name = "near square";
  const float h = kSquareHalfSize, z = -kSquareDistance;
  square.positions = {{-h, -h, z}, {h, -h, z}, {h, h, z}, {-h, h, z}};
  square.normals.assign(4, glm::vec3(0.0f, 0.0f, 1.0f));
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  square.material = static_cast<int>(scene.materials.size()) - 1;
  scene.meshes.push_back(square);
  return scene;
}

// Mean column of the yellow pixels (pixel centres at x + 0.5), or -1 if there are none.
double yellowCentroid(const ImageRGBA& image) {
  double sum = 0.0;
  std::size_t count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float* p = image.at(x, y);
      if (p[0] > 0.7f && p[1] > 0.7f && p[2] < 0.3f) {
        sum += x + 0.5;
        ++count;
      }
    }
  return count ? sum / double(count) : -1.0;
}

RenderSettings frontWall(const DisplayConfig& config, RenderMode mode, std::vector<Eye> eyes) {
  RenderSettings settings;
  settings.mode = mode;
  settings.eyes = std::move(eyes);
  settings.walls = {"front"};
  settings.resolutionScale = test::scaleFor(config, 128);
  return settings;
}

// The square's centre, seen from eye x = e onto the front wall 1.5 m away, lands at
// e + (0 - e) * 1.5 / 0.25 = -5 e: right of centre for the left eye (crossed disparity).
void expectClosedFormDisparity(const RenderResult& stereo, const DisplayConfig& config) {
  const Wall& front = config.wall("front");
  for (const WallImage& image : stereo.images) {
    const double eyeX = (image.eye == Eye::Left ? -0.5 : 0.5) * config.eyeSeparation;
    const double expectedX = eyeX + (0.0 - eyeX) * 1.5 / kSquareDistance;
    const double metresToPixels = image.image.width / front.widthMetres();
    EXPECT_NEAR(yellowCentroid(image.image), (expectedX - front.lowerLeft.x) * metresToPixels,
                0.5);
  }
  EXPECT_GT(yellowCentroid(imageOf(stereo, "front", Eye::Left).image),
            yellowCentroid(imageOf(stereo, "front", Eye::Right).image) + 5.0);
}

// Each layer of `stereo` equals the same eye rendered on its own.
void expectEqualToMonoRenders(RenderBackend& backend, const RenderResult& stereo,
                              const DisplayConfig& config, const RetargetMap& map,
                              RenderMode mode) {
  for (const WallImage& image : stereo.images) {
    const RenderResult mono = backend.render(config, &map, frontWall(config, mode, {image.eye}));
    const test::PixelComparison c = test::comparePixels(mono.images[0].image, image.image, 1e-5f);
    EXPECT_EQ(c.bad, 0u) << (image.eye == Eye::Left ? "left" : "right") << " eye, max "
                         << c.maxError;
  }
}

TEST(VulkanStereo, OneMultiviewPassShowsBothEyesWithTheClosedFormDisparity) {
  VulkanOptions options;
  options.stereoPasses = StereoPasses::Multiview;
  test::ValidatedBackend vk(options);
  const DisplayConfig config = test::loadConfig("cave5");
  vk->setScene(nearSquare(false));
  const RetargetMap identity = RetargetMap::identity(64);
  for (RenderMode mode : {RenderMode::Plain, RenderMode::Conformal}) {
    SCOPED_TRACE(mode == RenderMode::Plain ? "plain" : "conformal (identity map)");
    const RenderResult stereo =
        vk->render(config, &identity, frontWall(config, mode, {Eye::Left, Eye::Right}));
    EXPECT_EQ(stereo.stats.vulkan.value().viewsPerPass, 2);
    ASSERT_EQ(stereo.images.size(), 2u);
    EXPECT_EQ(stereo.images[0].eye, Eye::Left);
    EXPECT_EQ(stereo.images[1].eye, Eye::Right);
    expectClosedFormDisparity(stereo, config);
    expectEqualToMonoRenders(*vk.backend, stereo, config, identity, mode);
  }
  test::expectNoValidationMessages(vk);
}

TEST(VulkanStereo, DefaultStereoOfAFullSceneEqualsEachEyeRenderedAlone) {
  // Whichever way the startup probe chose (one multiview pass, or one pass per eye where the
  // driver misplaces clipped primitives), the images are those of each eye on its own.
  test::ValidatedBackend vk;
  const DisplayConfig config = test::loadConfig("cave5");
  vk->setScene(nearSquare(true));
  const RetargetMap identity = RetargetMap::identity(64);
  for (RenderMode mode : {RenderMode::Plain, RenderMode::Conformal}) {
    SCOPED_TRACE(mode == RenderMode::Plain ? "plain" : "conformal (identity map)");
    const RenderResult stereo =
        vk->render(config, &identity, frontWall(config, mode, {Eye::Left, Eye::Right}));
    expectClosedFormDisparity(stereo, config);
    expectEqualToMonoRenders(*vk.backend, stereo, config, identity, mode);
  }
  test::expectNoValidationMessages(vk);
}

TEST(VulkanStereo, TheStartupProbeTellsWhetherMultiviewDrawsClippedTrianglesCorrectly) {
  // Force one multiview pass on a scene whose triangles cross the wall's edges; the probe's
  // verdict (stats "stereo_passes" of a default backend) must predict whether that is right.
  const DisplayConfig config = test::loadConfig("cave5");
  const RetargetMap identity = RetargetMap::identity(16);
  test::ValidatedBackend automatic;
  automatic->setScene(nearSquare(true));
  const RenderResult probed = automatic->render(
      config, &identity, frontWall(config, RenderMode::Plain, {Eye::Left, Eye::Right}));
  const bool probeTrustsMultiview = probed.stats.vulkan.value().multiview;

  VulkanOptions options;
  options.stereoPasses = StereoPasses::Multiview;
  test::ValidatedBackend forced(options);
  forced->setScene(nearSquare(true));
  const RenderResult stereo = forced->render(
      config, &identity, frontWall(config, RenderMode::Plain, {Eye::Left, Eye::Right}));
  std::size_t bad = 0;
  for (std::size_t i = 0; i < 2; ++i)
    bad += test::comparePixels(stereo.images[i].image, probed.images[i].image, 1e-5f).bad;
  EXPECT_EQ(bad == 0, probeTrustsMultiview)
      << bad << " pixels differ; device " << probed.stats.vulkan.value().device;
  test::expectNoValidationMessages(automatic);
  test::expectNoValidationMessages(forced);
}

}  // namespace
}  // namespace confvis
