// The per-image ray tables (conformal centre eye, fast and exact stereo eyes): built on the second
// render of the same image, they must give exactly the pixels of a render that looks the map up
// per sample, and be skipped where they cannot apply (plain mode, a moved head, exact curves
// that bend near the scene).
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

RenderSettings stereoSettings(StereoRays rays) {
  RenderSettings stereo;
  stereo.mode = RenderMode::Conformal;
  stereo.eyes = {Eye::Left, Eye::Right};
  stereo.stereoRays = rays;
  stereo.resolutionScale = test::scaleFor(42);
  return stereo;
}

void expectSamePixels(const RenderResult& a, const RenderResult& b) {
  ASSERT_EQ(a.images.size(), b.images.size());
  for (std::size_t i = 0; i < a.images.size(); ++i) {
    SCOPED_TRACE(a.images[i].wall + " " + eyeName(a.images[i].eye));
    EXPECT_EQ(a.images[i].image.pixels, b.images[i].image.pixels);
  }
}

// Stereo eyes keep a table of their straight rays (fast rays: the targets W(p), shared by every
// head; exact rays: the tails beyond the bend, where the checker-sphere's 10 m keep beyond every
// curve's reach, per head): the same pixels as the per-sample rays, and a moved head gets no
// stale table.
TEST(EmbreeDirectionTable, StereoEyesReadTheirOwnTableFromTheSecondRender) {
  const DisplayConfig config = test::shippedConfig("cave5");
  const RetargetMap dilation = ceilinglessDilationMap(1.5, 128);
  EmbreeBackend backend;
  backend.setScene(builtinScene("checker-sphere"));
  for (StereoRays rays : {StereoRays::Fast, StereoRays::Exact}) {
    SCOPED_TRACE(stereoRaysName(rays));
    RenderSettings stereo = stereoSettings(rays);
    const RenderResult first = backend.render(config, &dilation, stereo);
    const RenderResult second = backend.render(config, &dilation, stereo);
    EXPECT_EQ(tableSamples(first), 0u);
    std::uint64_t samples = 0;
    for (const WallImage& image : second.images) samples += image.image.pixelCount();
    EXPECT_EQ(tableSamples(second), samples);
    expectSamePixels(first, second);
    // The head 2 cm to the right: the eyes' rays change. Exact tails belong to a head and must
    // not be reused; fast rays' targets W(p) serve every head (and both eyes) and are read at
    // once, drawing what a backend without the table draws per sample.
    stereo.head.position += glm::dvec3(0.02, 0.0, 0.0);
    const RenderResult moved = backend.render(config, &dilation, stereo);
    EXPECT_EQ(tableSamples(moved), rays == StereoRays::Fast ? samples : 0u);
    EXPECT_NE(moved.images[0].image.pixels, second.images[0].image.pixels);
    EmbreeBackend fresh;
    fresh.setScene(builtinScene("checker-sphere"));
    const RenderResult perSample = fresh.render(config, &dilation, stereo);
    EXPECT_EQ(tableSamples(perSample), 0u);
    expectSamePixels(moved, perSample);
    expectSamePixels(moved, backend.render(config, &dilation, stereo));  // its own table
  }
}

// Where the scene comes within the curves' reach (a square 0.4 m from c), exact stereo packets
// whose curves bend near it are marched as curves, not read as tails from the table (a tail
// starts 8 m out and would miss the square).
TEST(EmbreeDirectionTable, ExactStereoTablesGiveWayToCurvesNearTheScene) {
  const DisplayConfig config = test::shippedConfig("cave5");
  const RetargetMap dilation = ceilinglessDilationMap(1.5, 128);
  Scene scene = builtinScene("checker-sphere");
  scene.materials.push_back({"paint", glm::vec4(1, 1, 0, 1), -1});
  scene.meshes.push_back(
      test::facingSquare(0.4 * stereographicDilation({0, 0, -1}, 1.5), glm::dvec3(0.0), 0.2));
  scene.meshes.back().material = static_cast<int>(scene.materials.size()) - 1;
  EmbreeBackend backend;
  backend.setScene(scene);
  RenderSettings stereo = stereoSettings(StereoRays::Exact);
  stereo.walls = {"front"};
  const RenderResult first = backend.render(config, &dilation, stereo);
  const RenderResult second = backend.render(config, &dilation, stereo);
  EXPECT_GT(tableSamples(second), 0u);
  expectSamePixels(first, second);
  std::size_t yellow = 0;
  const ImageRGBA& left = second.images[0].image;
  for (std::size_t i = 0; i < left.pixelCount(); ++i)
    yellow += left.pixels[4 * i] > 0.9f && left.pixels[4 * i + 1] > 0.9f &&
              left.pixels[4 * i + 2] < 0.1f;
  EXPECT_GT(yellow, 20u) << "the square is not in view";
}

TEST(EmbreeDirectionTable, PlainRendersUseNoTable) {
  const DisplayConfig config = test::shippedConfig("cave5");
  EmbreeBackend& backend = test::checkerSphereBackend();
  RenderSettings plain;
  plain.mode = RenderMode::Plain;
  plain.eyes = {Eye::Left, Eye::Right};
  plain.resolutionScale = test::scaleFor(24);
  for (int i = 0; i < 2; ++i) EXPECT_EQ(tableSamples(backend.render(config, nullptr, plain)), 0u);
}

}  // namespace
}  // namespace confvis
