// renderInto, the frame-loop form of render: the previous frame's pixel storage is rendered over
// where the size agrees, and the pixels are those render() returns.
#include <gtest/gtest.h>

#include "confvis/backends/analytic_maps.hpp"
#include "render_test_support.hpp"

namespace confvis {
namespace {

using test::checkerSphereBackend;
using test::scaleFor;

RenderSettings settingsAt(RenderMode mode, int pixels) {
  RenderSettings settings;
  settings.mode = mode;
  settings.resolutionScale = scaleFor(pixels);
  return settings;
}

void expectSamePixels(const RenderResult& a, const RenderResult& b) {
  ASSERT_EQ(a.images.size(), b.images.size());
  for (std::size_t i = 0; i < a.images.size(); ++i) {
    EXPECT_EQ(a.images[i].wall, b.images[i].wall);
    EXPECT_EQ(a.images[i].image.width, b.images[i].image.width);
    EXPECT_EQ(a.images[i].image.pixels, b.images[i].image.pixels) << a.images[i].wall;
  }
}

TEST(EmbreeRenderInto, RendersOverThePreviousFramesStorageWithRendersPixels) {
  EmbreeBackend& backend = checkerSphereBackend();
  const DisplayConfig config = test::shippedConfig("cave5");
  const RetargetMap map = ceilinglessDilationMap(1.5, 64, config.reference);
  const RenderSettings plain = settingsAt(RenderMode::Plain, 40);
  const RenderSettings conformal = settingsAt(RenderMode::Conformal, 40);

  RenderResult frame;
  backend.renderInto(config, nullptr, plain, frame);
  expectSamePixels(frame, backend.render(config, nullptr, plain));
  std::vector<const float*> storage;
  for (const WallImage& image : frame.images) storage.push_back(image.image.pixels.data());

  // The next frame (another mode, different pixels) lands in the same memory, every pixel of it
  // rewritten: nothing of the plain frame may show through.
  backend.renderInto(config, &map, conformal, frame);
  expectSamePixels(frame, backend.render(config, &map, conformal));
  ASSERT_EQ(frame.images.size(), storage.size());
  for (std::size_t i = 0; i < storage.size(); ++i)
    EXPECT_EQ(frame.images[i].image.pixels.data(), storage[i]) << frame.images[i].wall;
  EXPECT_GT(static_cast<double>(frame.stats.embree.value().cameraRays), 0.0);

  // Another size: new images of that size, still render()'s pixels.
  const RenderSettings smaller = settingsAt(RenderMode::Plain, 24);
  backend.renderInto(config, nullptr, smaller, frame);
  expectSamePixels(frame, backend.render(config, nullptr, smaller));
  for (const WallImage& image : frame.images) EXPECT_EQ(image.image.width, 24);
}

}  // namespace
}  // namespace confvis
