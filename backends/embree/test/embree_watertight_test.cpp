// Camera rays must not slip through the checker-sphere, a closed mesh around the viewer: every
// pixel of every wall is covered, also where the pixel grid lines up with the mesh's vertices
// (small renders of the shipped CAVE at sizes dividing the sphere's grid). Robust mode closes
// the shared edges; the retry of a lone miss between hits closes the shared vertices.
#include <gtest/gtest.h>

#include "confvis/backends/analytic_maps.hpp"
#include "render_test_support.hpp"

namespace confvis {
namespace {

std::size_t uncoveredPixels(const RenderResult& result) {
  std::size_t missing = 0;
  for (const WallImage& image : result.images)
    for (std::size_t i = 0; i < image.image.pixelCount(); ++i)
      missing += image.image.pixels[4 * i + 3] < 1.0f;
  return missing;
}

TEST(EmbreeWatertight, NoPixelSlipsThroughTheClosedSphere) {
  const DisplayConfig config = test::shippedConfig("cave6");
  EmbreeBackend& backend = test::checkerSphereBackend();
  std::uint64_t retraced = 0;
  for (int pixels : {32, 48, 64, 96}) {
    SCOPED_TRACE(pixels);
    RenderSettings settings;
    settings.mode = RenderMode::Plain;
    settings.resolutionScale = test::scaleFor(pixels);
    const RenderResult plain = backend.render(config, nullptr, settings);
    EXPECT_EQ(uncoveredPixels(plain), 0u);
    retraced += plain.stats.embree.value().retracedRays;
    settings.mode = RenderMode::Conformal;
    const RetargetMap identity = RetargetMap::identity(128);
    EXPECT_EQ(uncoveredPixels(backend.render(config, &identity, settings)), 0u);
  }
  // The aligned grids do graze vertices: the retry is what covers them.
  EXPECT_GT(retraced, 0u);
}

TEST(EmbreeWatertight, RaysIntoEmptySpaceAreNotRetraced) {
  // A small square ahead on an empty background: misses far from any hit cost nothing extra,
  // and the square's silhouette stays where it is.
  EmbreeBackend backend;
  backend.setScene(test::squareScene({0.0, 0.0, -1.0}, 0.3, glm::vec3(1.0f)));
  RenderSettings settings;
  settings.mode = RenderMode::Plain;
  settings.resolutionScale = test::scaleFor(64);
  const RenderResult result = backend.render(test::shippedConfig("cave5"), nullptr, settings);
  const auto retraced = result.stats.embree.value().retracedRays;
  const auto rays = result.stats.embree.value().cameraRays;
  EXPECT_LT(retraced * 50, rays);
  std::size_t covered = 0;
  test::coverageCentroid(test::imageOf(result, "front", Eye::Center).image, &covered);
  EXPECT_GT(covered, 0u);
}

}  // namespace
}  // namespace confvis
