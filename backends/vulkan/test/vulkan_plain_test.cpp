// Plain (ordinary off-axis) rendering on lavapipe against closed forms: the checker-sphere seen
// from its centre shows checkerSphereColor(direction) at every pixel.
#include <gtest/gtest.h>

#include "confvis/engine/builtin_scenes.hpp"
#include "confvis/engine/view.hpp"
#include "vulkan_test_support.hpp"

namespace confvis {
namespace {

using test::ValidatedBackend;

using test::compareAnalytic;
using test::imageOf;

std::optional<glm::vec3> sphereColor(glm::dvec3 d) { return checkerSphereColor(d); }

TEST(VulkanPlain, CheckerSphereOnSixWallsMatchesTheAnalyticColours) {
  ValidatedBackend vk;
  const DisplayConfig config = test::loadConfig("cave6");
  vk->setScene(builtinScene("checker-sphere"));
  RenderSettings settings;
  settings.mode = RenderMode::Plain;
  settings.resolutionScale = test::scaleFor(config, 64);
  const RenderResult result = vk->render(config, nullptr, settings);
  ASSERT_EQ(result.images.size(), config.walls.size());
  for (std::size_t i = 0; i < config.walls.size(); ++i) {
    const WallImage& image = result.images[i];
    SCOPED_TRACE(image.wall);
    EXPECT_EQ(image.wall, config.walls[i].name);  // config order
    EXPECT_EQ(image.eye, Eye::Center);
    ASSERT_EQ(image.image.width, 64);
    ASSERT_EQ(image.image.height, 64);
    // Lambert with the headlight at the sphere's centre is 1 up to the tessellation of the
    // sphere (normals within ~3 degrees of the view ray).
    const test::AnalyticComparison c = compareAnalytic(image.image, config.walls[i], glm::dvec3(0.0),
                                                 sphereColor, 0.02f);
    EXPECT_GT(c.unambiguous, c.pixels * 6 / 10);
    EXPECT_LE(c.bad, c.unambiguous / 200) << c.bad << " of " << c.unambiguous << " pixels off";
  }
  // The comparison can fail: the left wall's image is not what the front wall shows.
  const test::AnalyticComparison wrong =
      compareAnalytic(imageOf(result, "left").image, config.wall("front"),
                      glm::dvec3(0.0), sphereColor, 0.02f);
  EXPECT_GT(wrong.bad, wrong.unambiguous / 4);
  test::expectNoValidationMessages(vk);
}

}  // namespace
}  // namespace confvis
