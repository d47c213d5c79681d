// Triangles that the source's cut crosses, split exactly along it in the pre-pass
// (split_triangles_at_cut.comp): each side is drawn up to the cut, against the closed form of
// the azimuth squeeze; without the split the geometry shader draws each side of the pieces the
// cut tears up to it too; dropping them instead (as once) leaves a band unshown beside it, which
// the test must see.
#include <gtest/gtest.h>

#include <string>

#include "confvis/engine/builtin_scenes.hpp"
#include "vulkan_test_maps.hpp"
#include "vulkan_test_support.hpp"

namespace confvis {
namespace {

using test::imageOf;

TEST(VulkanCutSplit, TrianglesAcrossTheCutAreDrawnUpToItOnEachSide) {
  // The squeeze's cut, the back half-meridian, lands on the middle column of cave6's side walls:
  // in front of it (z < 0) every pixel shows the sphere, behind it nothing.
  const DisplayConfig config = test::loadConfig("cave6");
  const RetargetMap squeeze = test::azimuthSqueezeMap(256);
  BuiltinSceneOptions sceneOptions;
  sceneOptions.subdivision = 15;  // 2,700 triangles of about 6 degrees, none with an edge on the cut
  const Scene scene = builtinScene("checker-sphere", sceneOptions);
  const auto render = [&](bool split, bool geometryShaderSplit = true) {
    VulkanOptions options;
    options.splitAlongCut = split;
    options.drawTornPiecesUpToTheCut = geometryShaderSplit;
    // Segments across the cut of four times this (six pixels): the band the drop leaves is
    // as wide as one.
    options.tessellationErrorPixels = 1.5;
    test::ValidatedBackend vk(options);
    vk->setScene(scene);
    RenderSettings settings;
    settings.mode = RenderMode::Conformal;
    settings.resolutionScale = test::scaleFor(config, 128);
    RenderResult result = vk->render(config, &squeeze, settings);
    test::expectNoValidationMessages(vk);
    return result;
  };
  // Pixels whose centre lies 0.5 to 4 pixels in front of the cut's column, away from the poles
  // (the top and bottom eighth, where the cut ends), and those of them that show nothing.
  struct Beside {
    std::size_t pixels = 0, holes = 0;
  };
  const auto besideTheCut = [&](const RenderResult& result) {
    Beside b;
    for (const char* name : {"left", "right"}) {
      const Wall& wall = config.wall(name);
      const ImageRGBA& image = imageOf(result, name).image;
      const double pixel = glm::length(wall.lowerRight - wall.lowerLeft) / image.width;
      for (int y = image.height / 8; y < image.height * 7 / 8; ++y)
        for (int x = 0; x < image.width; ++x) {
          const double z = wall.pointAt((x + 0.5) / image.width, 0.5).z;
          if (z > -0.5 * pixel || z < -4.0 * pixel) continue;
          ++b.pixels;
          b.holes += image.at(x, y)[3] == 0.0f;
        }
    }
    return b;
  };
  const test::DirectionColor expected = [](glm::dvec3 d) -> std::optional<glm::vec3> {
    const auto v = test::squeezeToVirtual(glm::normalize(d));
    if (!v) return std::nullopt;
    return checkerSphereColor(*v);
  };

  const RenderResult split = render(true);
  // The sphere's rings of triangles around the half-meridian, between the poles.
  EXPECT_GE(split.stats.vulkan.value().conformalPrepass.value().trianglesSplitAlongCut, 16u);
  const Beside b = besideTheCut(split);
  EXPECT_GT(b.pixels, 500u);
  EXPECT_LE(b.holes, b.pixels / 100) << b.holes << " of " << b.pixels << " pixels beside the cut";
  for (const char* name : {"left", "right"}) {
    SCOPED_TRACE(name);
    const test::AnalyticComparison a = test::compareAnalytic(
        imageOf(split, name).image, config.wall(name), glm::dvec3(0.0), expected, 0.05f);
    EXPECT_LE(a.bad, a.unambiguous / 100) << a.bad << " of " << a.unambiguous << " pixels off";
  }
  // Behind the cut's column nothing is drawn: no piece was given the other side's warp.
  EXPECT_EQ(test::drawnPixels(imageOf(split, "back").image), 0u);

  // Without the split the pieces across the cut go through the geometry shader, which draws
  // each side of a torn piece up to the cut too (warp.geom, splitAtCut; it dropped them before,
  // leaving a band here of 10 % and more of these pixels).
  const RenderResult unsplit = render(false);
  EXPECT_EQ(unsplit.stats.vulkan.value().conformalPrepass.value().trianglesSplitAlongCut, 0u);
  const Beside d = besideTheCut(unsplit);
  EXPECT_LE(d.holes, d.pixels / 100) << d.holes << " of " << d.pixels << " pixels beside the cut";

  // Deliberately broken: neither split, the pieces across the cut dropped by the geometry shader
  // (VulkanOptions::drawTornPiecesUpToTheCut off, as before issue 23), leave the band beside the
  // cut unshown that the splits fill: the hole count above fails (measured: 83 of 768 pixels
  // dropped, none with either split).
  const RenderResult dropped = render(false, false);
  const Beside h = besideTheCut(dropped);
  RecordProperty("holes_beside_the_cut_split", std::to_string(b.holes));
  RecordProperty("holes_beside_the_cut_unsplit", std::to_string(d.holes));
  RecordProperty("holes_beside_the_cut_dropped", std::to_string(h.holes));
  RecordProperty("pixels_beside_the_cut", std::to_string(h.pixels));
  EXPECT_GT(h.holes, h.pixels / 20) << h.holes << " of " << h.pixels << " pixels beside the cut";

  // Deliberately broken: the same drawing against the sphere unsqueezed fails the comparison.
  const test::DirectionColor unsqueezed = [](glm::dvec3 v) -> std::optional<glm::vec3> {
    return checkerSphereColor(glm::normalize(v));
  };
  const test::AnalyticComparison wrong = test::compareAnalytic(
      imageOf(split, "left").image, config.wall("left"), glm::dvec3(0.0), unsqueezed, 0.05f);
  EXPECT_GT(wrong.bad, wrong.unambiguous / 10) << wrong.bad << " of " << wrong.unambiguous;
}

}  // namespace
}  // namespace confvis
