// The conformal pre-pass is reused by a frame whose scene, map, navigation and error bounds are
// the previous conformal frame's (VulkanOptions::reusePrepass): head tracking alone reuses it,
// navigating or a new map runs it again, and every frame draws what a fresh backend draws.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "confvis/engine/builtin_scenes.hpp"
#include "vulkan_image_checks.hpp"
#include "vulkan_test_maps.hpp"
#include "vulkan_test_support.hpp"

namespace confvis {
namespace {

// Largest channel difference between two renders' images, all walls.
double largestDifference(const RenderResult& a, const RenderResult& b) {
  EXPECT_EQ(a.images.size(), b.images.size());
  double largest = 0.0;
  for (std::size_t i = 0; i < a.images.size() && i < b.images.size(); ++i)
    largest = std::max(
        largest, test::comparePixels(a.images[i].image, b.images[i].image, 0.0f).maxError);
  return largest;
}

TEST(VulkanPrepassReuse, HeadMovesReuseItNavigationAndMapsRunItAgain) {
  const DisplayConfig config = test::loadConfig("cave5");
  BuiltinSceneOptions sceneOptions;
  sceneOptions.subdivision = 8;
  const Scene scene = builtinScene("checker-sphere", sceneOptions);
  const RetargetMap squeeze = test::azimuthSqueezeMap(64);  // a cut: every list is drawn
  const RetargetMap zoom = test::zoomMap(64, 2.0);
  RenderSettings settings;
  settings.mode = RenderMode::Conformal;
  settings.resolutionScale = test::scaleFor(config, 64);

  test::ValidatedBackend vk;
  vk->setScene(scene);
  // What a backend that has drawn nothing before draws.
  const auto fresh = [&](const RetargetMap& map, const RenderSettings& s) {
    test::ValidatedBackend other;
    other->setScene(scene);
    return other->render(config, &map, s);
  };
  const auto reused = [](const RenderResult& r) {
    return r.stats.vulkan.value().conformalPrepass.value().prepassReused;
  };

  EXPECT_FALSE(reused(vk->render(config, &squeeze, settings)));
  RenderSettings headMoved = settings;
  headMoved.head.position = glm::dvec3(0.2, -0.1, 0.3);
  const RenderResult head = vk->render(config, &squeeze, headMoved);
  EXPECT_TRUE(reused(head));
  EXPECT_EQ(largestDifference(head, fresh(squeeze, headMoved)), 0.0);

  RenderSettings navigated = headMoved;
  navigated.camera.yawDegrees = 30.0;
  const RenderResult turned = vk->render(config, &squeeze, navigated);
  EXPECT_FALSE(reused(turned));
  EXPECT_EQ(largestDifference(turned, fresh(squeeze, navigated)), 0.0);
  // (The comparisons can fail: the turned frame differs from the one before.)
  EXPECT_GT(largestDifference(turned, head), 0.5);

  const RenderResult zoomed = vk->render(config, &zoom, navigated);
  EXPECT_FALSE(reused(zoomed));
  EXPECT_EQ(largestDifference(zoomed, fresh(zoom, navigated)), 0.0);
  test::expectNoValidationMessages(vk);
}

TEST(VulkanPrepassReuse, GpuTimeCountsThePrepassOnlyWhereItRan) {
  // The frame's GPU time (timestamps around the pre-pass and each wall's render pass) is what the
  // benchmark compares on a GPU: it must include a pre-pass that ran and nothing for one reused.
  const DisplayConfig config = test::loadConfig("cave5");
  test::ValidatedBackend vk;
  BuiltinSceneOptions sceneOptions;
  sceneOptions.subdivision = 40;  // 19k triangles: a pre-pass long enough to measure
  vk->setScene(builtinScene("checker-sphere", sceneOptions));
  const RetargetMap squeeze = test::azimuthSqueezeMap(64);
  RenderSettings settings;
  settings.resolutionScale = test::scaleFor(config, 32);
  settings.mode = RenderMode::Plain;
  // -1 where the frame has no such time.
  const auto gpu = [](const RenderResult& r) {
    return r.stats.vulkan.value().gpuSeconds.value_or(-1.0);
  };
  const auto prepassGpu = [](const RenderResult& r) {
    return r.stats.vulkan.value().conformalPrepass.value().prepassGpuSeconds.value_or(-1.0);
  };

  const RenderResult plain = vk->render(config, nullptr, settings);
  EXPECT_GT(gpu(plain), 0.0);
  EXPECT_FALSE(plain.stats.vulkan.value().conformalPrepass);  // no pre-pass in plain mode
  settings.mode = RenderMode::Conformal;
  const RenderResult ran = vk->render(config, &squeeze, settings);
  const RenderResult reused = vk->render(config, &squeeze, settings);
  ASSERT_TRUE(reused.stats.vulkan.value().conformalPrepass.value().prepassReused);
  EXPECT_GT(prepassGpu(ran), 0.0);
  EXPECT_LT(prepassGpu(ran), gpu(ran));
  EXPECT_EQ(prepassGpu(reused), 0.0);
  EXPECT_GT(gpu(reused), 0.0);
  // A pre-pass over 19k triangles takes longer than 1 µs, the frame less than a minute: the
  // timestamp period and valid bits are applied.
  EXPECT_GT(prepassGpu(ran), 1e-6);
  EXPECT_LT(gpu(ran), 60.0);
  test::expectNoValidationMessages(vk);
}

TEST(VulkanPrepassReuse, TimedPassesSplitThePrepassWithoutChangingTheImages) {
  // VulkanOptions::timePrepassPasses (the benchmark's per-pass table): one time per pass, in
  // order, adding up to the pre-pass's GPU time; none where the pre-pass was reused or the option
  // is off; the timestamps between the passes change nothing drawn.
  const DisplayConfig config = test::loadConfig("cave5");
  BuiltinSceneOptions sceneOptions;
  sceneOptions.subdivision = 40;
  const Scene scene = builtinScene("checker-sphere", sceneOptions);
  const RetargetMap squeeze = test::azimuthSqueezeMap(64);
  RenderSettings settings;
  settings.resolutionScale = test::scaleFor(config, 32);
  settings.mode = RenderMode::Conformal;
  VulkanOptions timedOptions;
  timedOptions.timePrepassPasses = true;
  test::ValidatedBackend timed(timedOptions), untimed;
  timed->setScene(scene);
  untimed->setScene(scene);

  const RenderResult ran = timed->render(config, &squeeze, settings);
  const RenderResult plainRun = untimed->render(config, &squeeze, settings);
  EXPECT_TRUE(plainRun.stats.vulkan.value().conformalPrepass.value().passGpuSeconds.empty());
  EXPECT_EQ(largestDifference(ran, plainRun), 0.0);
  const VulkanConformalStats& ranPrepass = ran.stats.vulkan.value().conformalPrepass.value();
  if (!ranPrepass.prepassGpuSeconds) GTEST_SKIP() << "no timestamps on this queue";
  const std::map<std::string, double>& passes = ranPrepass.passGpuSeconds;
  const auto listed = [&] {
    std::string names;
    for (const auto& [name, seconds] : passes) names += name + " ";
    return names;
  };
  const std::vector<std::string> expected = {
      "warp_vertices",       "warp_vertices_across_cut",    "classify_edges",
      "classify_edges_bent", "classify_edges_at_cut",       "classify_triangles",
      "classify_straight_triangles", "classify_bent_triangles", "split_triangles_at_cut"};
  ASSERT_EQ(passes.size(), expected.size()) << listed();
  double sum = 0.0;
  for (const std::string& name : expected) {
    ASSERT_TRUE(passes.count(name)) << name << " in " << listed();
    EXPECT_GE(passes.at(name), 0.0) << name;
    sum += passes.at(name);
  }
  // Passes over every vertex, edge and triangle of 19k triangles take measurable time.
  for (const char* name : {"warp_vertices", "classify_edges", "classify_triangles"})
    EXPECT_GT(passes.at(name), 0.0) << name;
  const double total = *ranPrepass.prepassGpuSeconds;
  EXPECT_NEAR(sum, total, 1e-6 * total + 1e-9);
  const RenderResult reused = timed->render(config, &squeeze, settings);
  ASSERT_TRUE(reused.stats.vulkan.value().conformalPrepass.value().prepassReused);
  EXPECT_TRUE(reused.stats.vulkan.value().conformalPrepass.value().passGpuSeconds.empty());
  test::expectNoValidationMessages(timed);
  test::expectNoValidationMessages(untimed);
}

TEST(VulkanPrepassReuse, SwitchedOffEveryFrameRunsIt) {
  const DisplayConfig config = test::loadConfig("cave5");
  VulkanOptions options;
  options.reusePrepass = false;
  test::ValidatedBackend vk(options);
  vk->setScene(builtinScene("checker-sphere"));
  const RetargetMap zoom = test::zoomMap(64, 2.0);
  RenderSettings settings;
  settings.mode = RenderMode::Conformal;
  settings.resolutionScale = test::scaleFor(config, 32);
  for (int frame = 0; frame < 2; ++frame) {
    const RenderResult result = vk->render(config, &zoom, settings);
    EXPECT_FALSE(result.stats.vulkan.value().conformalPrepass.value().prepassReused);
  }
  test::expectNoValidationMessages(vk);
}

}  // namespace
}  // namespace confvis
