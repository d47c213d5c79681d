// RenderBackend::prepare runs a frame's one-off work before the loop (the Vulkan backend's
// pipelines); it must leave nothing behind that changes a later frame: a prepared backend's
// first frame, through a different map than prepare's identity, equals an unprepared backend's
// pixel for pixel. (What prepare saves is a time, measured by the benchmarks, not asserted here.)
#include <gtest/gtest.h>

#include <cmath>

#include "../backends/vulkan/test/vulkan_test_support.hpp"
#include "confvis/backends/analytic_maps.hpp"
#include "confvis/backends/embree/embree_backend.hpp"
#include "confvis/backends/render_plan.hpp"
#include "confvis/engine/builtin_scenes.hpp"

namespace confvis {
namespace {

using BackendFactory = std::function<std::unique_ptr<RenderBackend>()>;

void expectPreparedFrameEqualsUnprepared(const BackendFactory& make) {
  const DisplayConfig config = test::loadConfig("cave5");
  const Scene scene = builtinScene("checker-sphere");
  RenderSettings settings;
  settings.mode = RenderMode::Conformal;
  settings.eyes = {Eye::Left, Eye::Right};
  settings.resolutionScale = test::scaleFor(config, 24);
  const RetargetMap map = ceilinglessDilationMap(1.6, 32, config.reference);

  const std::unique_ptr<RenderBackend> prepared = make(), unprepared = make();
  prepared->setScene(scene);
  unprepared->setScene(scene);
  prepared->prepare(config, settings);
  RenderResult afterPrepare, fresh;
  prepared->renderInto(config, &map, settings, afterPrepare);
  unprepared->renderInto(config, &map, settings, fresh);

  ASSERT_EQ(afterPrepare.images.size(), 2 * config.walls.size());
  ASSERT_EQ(fresh.images.size(), afterPrepare.images.size());
  int drawn = 0;
  for (std::size_t i = 0; i < fresh.images.size(); ++i) {
    const ImageRGBA &a = afterPrepare.images[i].image, &b = fresh.images[i].image;
    ASSERT_EQ(a.width, b.width);
    ASSERT_EQ(a.height, b.height);
    EXPECT_EQ(a.pixels, b.pixels) << fresh.images[i].wall << " " << eyeName(fresh.images[i].eye);
    for (std::size_t p = 3; p < b.pixels.size(); p += 4) drawn += b.pixels[p] > 0.5f;
  }
  EXPECT_GT(drawn, 0);  // the comparison is over drawn pictures, not empty ones
}

TEST(BackendPrepare, EmbreeFrameAfterPrepareEqualsAnUnpreparedOne) {
  expectPreparedFrameEqualsUnprepared([] { return std::make_unique<EmbreeBackend>(); });
}

TEST(BackendPrepare, VulkanFrameAfterPrepareEqualsAnUnpreparedOne) {
  expectPreparedFrameEqualsUnprepared([] {
    VulkanOptions options;
    options.device = test::testDevice();
    return makeVulkanBackend(options);
  });
}

}  // namespace
}  // namespace confvis
