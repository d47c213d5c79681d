// Plain (ordinary off-axis) rendering on lavapipe against closed forms: the checker-sphere seen
// from its centre shows checkerSphereColor(direction) at every pixel.
#include <gtest/gtest.h>

#include <functional>

#include "confvis/engine/builtin_scenes.hpp"
#include "confvis/engine/view.hpp"
#include "vulkan_test_support.hpp"

namespace confvis {
namespace {

using test::ValidatedBackend;

// Colour the scene shows along a direction from the eye.
using DirectionColor = std::function<glm::vec3(glm::dvec3)>;

struct AnalyticComparison {
  std::size_t pixels = 0, unambiguous = 0, bad = 0;
};

// Compares `image` (a render of `wall` seen from `eye`) with `expected` at every pixel whose
// centre and four half-pixel neighbours all have the same expected colour; pixels on a colour
// edge are left out, since rasterization places edges only to within a pixel.
AnalyticComparison compareAnalytic(const ImageRGBA& image, const Wall& wall, glm::dvec3 eye,
                                   const DirectionColor& expected, float tolerance) {
  const WallView view = makeWallView(wall, eye);
  const double sx = double(wall.width) / image.width, sy = double(wall.height) / image.height;
  AnalyticComparison c;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      ++c.pixels;
      const auto colorAt = [&](double dx, double dy) {
        return expected(view.rayDirection((x + 0.5 + dx) * sx, (y + 0.5 + dy) * sy));
      };
      const glm::vec3 centre = colorAt(0, 0);
      bool same = true;
      for (auto [dx, dy] : {std::pair{-0.5, 0.0}, {0.5, 0.0}, {0.0, -0.5}, {0.0, 0.5}})
        same = same && glm::all(glm::equal(colorAt(dx, dy), centre));
      if (!same) continue;
      ++c.unambiguous;
      const float* p = image.at(x, y);
      const float error = std::max({std::abs(p[0] - centre.r), std::abs(p[1] - centre.g),
                                    std::abs(p[2] - centre.b), std::abs(p[3] - 1.0f)});
      if (error > tolerance) ++c.bad;
    }
  return c;
}

const WallImage& imageOf(const RenderResult& result, const std::string& wall, Eye eye) {
  for (const WallImage& image : result.images)
    if (image.wall == wall && image.eye == eye) return image;
  throw std::runtime_error("no image for wall " + wall);
}

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
    const AnalyticComparison c = compareAnalytic(image.image, config.walls[i], glm::dvec3(0.0),
                                                 checkerSphereColor, 0.02f);
    EXPECT_GT(c.unambiguous, c.pixels * 6 / 10);
    EXPECT_LE(c.bad, c.unambiguous / 200) << c.bad << " of " << c.unambiguous << " pixels off";
  }
  // The comparison can fail: the left wall's image is not what the front wall shows.
  const AnalyticComparison wrong =
      compareAnalytic(imageOf(result, "left", Eye::Center).image, config.wall("front"),
                      glm::dvec3(0.0), checkerSphereColor, 0.02f);
  EXPECT_GT(wrong.bad, wrong.unambiguous / 4);
  test::expectNoValidationMessages(vk);
}

}  // namespace
}  // namespace confvis
