// frameStats reads a backend's frame statistics into the typed FrameStats: the figures that can be
// known in advance are checked against their closed forms (one camera ray per pixel of a plain
// mono frame and one per retrace, the scene's triangle count, the pre-pass reused by an unchanged
// second frame).
#include <gtest/gtest.h>

#include "../backends/vulkan/test/vulkan_test_support.hpp"
#include "confvis/backends/analytic_maps.hpp"
#include "confvis/backends/embree/embree_backend.hpp"
#include "confvis/backends/frame_stats.hpp"
#include "confvis/base/error.hpp"
#include "confvis/engine/builtin_scenes.hpp"

namespace confvis {
namespace {

TEST(FrameStats, EmbreeCountsOneCameraRayPerPixelOfAPlainMonoFrame) {
  const DisplayConfig config = test::loadConfig("cave5");
  const Scene scene = builtinScene("checker-sphere");
  EmbreeBackend backend;
  backend.setScene(scene);
  RenderSettings settings;
  settings.mode = RenderMode::Plain;
  settings.resolutionScale = test::scaleFor(config, 16);
  const FrameStats stats = frameStats(backend.render(config, nullptr, settings));
  EXPECT_EQ(stats.backend, "embree");
  EXPECT_GT(stats.seconds, 0.0);
  EXPECT_EQ(stats.sceneTriangles, scene.triangleCount());
  ASSERT_TRUE(stats.cameraRays && stats.retracedRays && stats.raysPerSecond && stats.threads);
  EXPECT_EQ(*stats.cameraRays, 16u * 16u * config.walls.size() + *stats.retracedRays);
  EXPECT_LT(*stats.retracedRays, *stats.cameraRays / 10);
  EXPECT_EQ(stats.occlusionRays.value_or(0), 0u);  // no ambient occlusion asked for
  EXPECT_NEAR(*stats.raysPerSecond, *stats.cameraRays / stats.seconds, 1e-6 * *stats.raysPerSecond);
  EXPECT_GE(*stats.threads, 1);
  EXPECT_FALSE(stats.gpuSeconds);
  EXPECT_TRUE(stats.device.empty());
}

TEST(FrameStats, VulkanReportsItsDeviceAndTheReusedPrepass) {
  const DisplayConfig config = test::loadConfig("cave5");
  const Scene scene = builtinScene("checker-sphere");
  VulkanOptions options;
  options.device = test::testDevice();
  const std::unique_ptr<RenderBackend> backend = makeVulkanBackend(options);
  backend->setScene(scene);
  RenderSettings settings;
  settings.resolutionScale = test::scaleFor(config, 16);
  const RetargetMap map = ceilinglessDilationMap(1.6, 16, config.reference);
  RenderResult result;
  backend->renderInto(config, &map, settings, result);
  const FrameStats first = frameStats(result);
  backend->renderInto(config, &map, settings, result);  // nothing changed: the pre-pass is kept
  const FrameStats second = frameStats(result);
  EXPECT_EQ(first.backend, "vulkan");
  EXPECT_NE(first.device.find(test::kLavapipe), std::string::npos) << first.device;
  EXPECT_EQ(first.sceneTriangles, scene.triangleCount());
  EXPECT_GT(first.seconds, 0.0);
  ASSERT_TRUE(first.prepassReused && second.prepassReused && first.prepassSeconds);
  EXPECT_FALSE(*first.prepassReused);
  EXPECT_TRUE(*second.prepassReused);
  EXPECT_FALSE(first.cameraRays);  // a rasterizer shoots no rays
}

TEST(FrameStats, AResultNoBackendMadeIsOneErrorNamingTheKey) {
  try {
    frameStats(RenderResult{});
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_EQ(error.code(), ErrorCode::InvalidInput);
    EXPECT_NE(std::string(error.what()).find("\"backend\""), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace confvis
