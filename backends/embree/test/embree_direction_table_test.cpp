// The per-image direction table (conformal centre eye): built on the second render of the same
// image, it must give exactly the pixels of a render that looks the map up per sample, and be
// skipped where it cannot apply (stereo eyes, plain mode).
#include <gtest/gtest.h>

#include "confvis/backends/analytic_maps.hpp"
#include "render_test_support.hpp"

namespace confvis {
namespace {

std::uint64_t tableSamples(const RenderResult& result) {
  return result.stats.embree.value().directionTableSamples;
}

TEST(EmbreeDirectionTable, SecondRenderReadsTheTableAndDrawsTheSamePixels) {
  const DisplayConfig config = test::shippedConfig("cave5");
  const RetargetMap dilation = ceilinglessDilationMap(1.5, 128);
  EmbreeBackend backend;  // its own table cache
  backend.setScene(builtinScene("checker-sphere"));
  for (int spp : {1, 4}) {  // 4: the table indexes samples within a pixel too
    SCOPED_TRACE(spp);
    RenderSettings settings;
    settings.mode = RenderMode::Conformal;
    settings.resolutionScale = test::scaleFor(42);  // 42: tiles 16 + 16 + 10 wide, a short packet
    settings.samplesPerPixel = spp;
    const RenderResult first = backend.render(config, &dilation, settings);
    const RenderResult second = backend.render(config, &dilation, settings);
    EXPECT_EQ(tableSamples(first), 0u) << "a one-shot render must not pay for a table";
    std::uint64_t samples = 0;
    for (const WallImage& image : second.images) samples += image.image.pixelCount() * spp;
    EXPECT_EQ(tableSamples(second), samples);
    ASSERT_EQ(first.images.size(), second.images.size());
    for (std::size_t i = 0; i < first.images.size(); ++i) {
      SCOPED_TRACE(first.images[i].wall);
      EXPECT_EQ(first.images[i].image.pixels, second.images[i].image.pixels);
    }
    // Another map must not reuse the table: its render differs from the dilation's.
    const RetargetMap identity = RetargetMap::identity(128);
    const RenderResult other = backend.render(config, &identity, settings);
    EXPECT_EQ(tableSamples(other), 0u);
    EXPECT_NE(other.images[0].image.pixels, second.images[0].image.pixels);
  }
}

TEST(EmbreeDirectionTable, StereoEyesAndPlainRendersUseNoTable) {
  const DisplayConfig config = test::shippedConfig("cave5");
  const RetargetMap dilation = ceilinglessDilationMap(1.5, 128);
  EmbreeBackend& backend = test::checkerSphereBackend();
  RenderSettings stereo;
  stereo.mode = RenderMode::Conformal;
  stereo.eyes = {Eye::Left, Eye::Right};
  stereo.resolutionScale = test::scaleFor(24);
  for (int i = 0; i < 2; ++i) EXPECT_EQ(tableSamples(backend.render(config, &dilation, stereo)), 0u);
  RenderSettings plain = stereo;
  plain.mode = RenderMode::Plain;
  plain.eyes = {Eye::Center};
  for (int i = 0; i < 2; ++i) EXPECT_EQ(tableSamples(backend.render(config, nullptr, plain)), 0u);
}

}  // namespace
}  // namespace confvis
