// Application-supplied view and projection per wall and eye (RenderSettings::views), both
// backends: the matrices confvis computes itself give the same pixels, and a translated view
// moves a known object by what projecting it with the two matrices predicts.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "../backends/vulkan/test/vulkan_test_maps.hpp"
#include "../backends/vulkan/test/vulkan_test_scenes.hpp"
#include "../backends/vulkan/test/vulkan_test_support.hpp"
#include "confvis/backends/embree/embree_backend.hpp"
#include "confvis/backends/render_plan.hpp"
#include "confvis/base/error.hpp"
#include "confvis/engine/view.hpp"

namespace confvis {
namespace {

constexpr int kPixels = 96;
const glm::vec3 kMarkerCentre(0.1f, -0.05f, -1.0f);

// One red square 1 m in front of the centre of cave6, facing it; nothing else (alpha 0 around).
Scene markerScene() {
  Scene scene;
  const int red = test::addMaterial(scene, "red", glm::vec4(0.9f, 0.1f, 0.1f, 1.0f));
  scene.meshes.push_back(
      test::quad("marker", kMarkerCentre, {0.12f, 0, 0}, {0, 0.12f, 0}, red));
  return scene;
}

RenderSettings frontSettings(const DisplayConfig& config, RenderMode mode) {
  RenderSettings settings;
  settings.mode = mode;
  settings.walls = {"front"};
  settings.resolutionScale = test::scaleFor(config, kPixels);
  return settings;
}

// What confvis computes for the front wall's centre eye, with a forward-Z projection (the
// backends replace the depth row).
ViewOverride computedView(const DisplayConfig& config) {
  const WallView view = makeWallView(config.wall("front"), config.reference);
  return {"front", Eye::Center, view.view, view.projectionVulkan(0.1, 100.0)};
}

std::unique_ptr<RenderBackend> makeBackend(const std::string& name) {
  if (name == "embree") return std::make_unique<EmbreeBackend>();
  VulkanOptions options;
  options.device = test::testDevice();
  return makeVulkanBackend(options);
}

// Centroid of the drawn pixels (alpha above 0.5), in pixels.
glm::dvec2 drawnCentroid(const ImageRGBA& image) {
  glm::dvec2 sum(0.0);
  double count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (image.at(x, y)[3] > 0.5f) {
        sum += glm::dvec2(x + 0.5, y + 0.5);
        ++count;
      }
  return count > 0 ? sum / count : glm::dvec2(-1e9);
}

// Where `viewProjection` puts physical point p in a width x height image (y down).
glm::dvec2 projectToPixels(const glm::dmat4& viewProjection, glm::dvec3 p, int width, int height) {
  const glm::dvec4 clip = viewProjection * glm::dvec4(p, 1.0);
  return {(clip.x / clip.w + 1.0) * 0.5 * width, (clip.y / clip.w + 1.0) * 0.5 * height};
}

class ViewOverrides : public ::testing::TestWithParam<std::string> {};

TEST_P(ViewOverrides, TheComputedMatricesGiveTheSamePixels) {
  const DisplayConfig config = test::loadConfig("cave6");
  std::unique_ptr<RenderBackend> backend = makeBackend(GetParam());
  backend->setScene(markerScene());
  const RetargetMap map = test::rotationMap(64, 10.0);
  for (RenderMode mode : {RenderMode::Plain, RenderMode::Conformal}) {
    SCOPED_TRACE(modeName(mode));
    RenderSettings settings = frontSettings(config, mode);
    const RenderResult computed = backend->render(config, &map, settings);
    settings.views = {computedView(config)};
    const RenderResult supplied = backend->render(config, &map, settings);
    ASSERT_EQ(supplied.images.size(), 1u);
    ASSERT_GT(test::drawnPixels(computed.images[0].image), 100u);
    const test::PixelComparison same =
        test::comparePixels(computed.images[0].image, supplied.images[0].image, 1e-6f);
    EXPECT_EQ(same.bad, 0u) << "max error " << same.maxError;
  }
}

TEST_P(ViewOverrides, ATranslatedViewMovesTheMarkerAsProjectionPredicts) {
  const DisplayConfig config = test::loadConfig("cave6");
  std::unique_ptr<RenderBackend> backend = makeBackend(GetParam());
  backend->setScene(markerScene());
  RenderSettings settings = frontSettings(config, RenderMode::Plain);
  const ViewOverride computed = computedView(config);
  ViewOverride moved = computed;
  // The eye space shifted 8 cm left and 5 cm up: the scene moves right and down... as P V' says.
  moved.view = glm::translate(glm::dmat4(1.0), glm::dvec3(0.08, -0.05, 0.0)) * computed.view;
  settings.views = {computed};
  const ImageRGBA before = backend->render(config, nullptr, settings).images[0].image;
  settings.views = {moved};
  const ImageRGBA after = backend->render(config, nullptr, settings).images[0].image;
  const glm::dvec2 predicted =
      projectToPixels(moved.projection * moved.view, kMarkerCentre, after.width, after.height) -
      projectToPixels(computed.projection * computed.view, kMarkerCentre, before.width,
                      before.height);
  ASSERT_GT(glm::length(predicted), 4.0) << "the shift must be visible";
  const glm::dvec2 measured = drawnCentroid(after) - drawnCentroid(before);
  EXPECT_NEAR(measured.x, predicted.x, 0.5);
  EXPECT_NEAR(measured.y, predicted.y, 0.5);
  // The check can fail: without the override the marker stays where it was.
  settings.views.clear();
  const ImageRGBA unmoved = backend->render(config, nullptr, settings).images[0].image;
  EXPECT_GT(glm::length(drawnCentroid(unmoved) - drawnCentroid(before) - predicted), 3.0);
}

TEST_P(ViewOverrides, BadOverridesAreOneClearError) {
  const DisplayConfig config = test::loadConfig("cave6");
  std::unique_ptr<RenderBackend> backend = makeBackend(GetParam());
  backend->setScene(markerScene());
  RenderSettings settings = frontSettings(config, RenderMode::Plain);
  const auto message = [&](ViewOverride v) -> std::string {
    settings.views = {v};
    try {
      backend->render(config, nullptr, settings);
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::InvalidInput);
      return e.what();
    }
    return "no error";
  };
  ViewOverride unknown = computedView(config);
  unknown.wall = "attic";
  EXPECT_NE(message(unknown).find("'attic'"), std::string::npos);
  ViewOverride singular = computedView(config);
  singular.view = glm::dmat4(0.0);
  singular.view[3][3] = 1.0;
  EXPECT_NE(message(singular).find("not an invertible affine"), std::string::npos);
  ViewOverride notFinite = computedView(config);
  notFinite.projection[0][0] = std::nan("");
  EXPECT_NE(message(notFinite).find("not finite"), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(Backends, ViewOverrides, ::testing::Values("embree", "vulkan"));

}  // namespace
}  // namespace confvis
