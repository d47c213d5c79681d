// Stereo in conformal mode (design note §5): a near object shows crossed parallax with both
// exact (curved) and fast (straight) stereo rays; the two agree on the centre eye; the curved
// rays are marched finely enough; and the difference between exact and fast stereo is measured
// (reported as test properties, see the README's rendering notes).
#include <gtest/gtest.h>

#include <cstdio>

#include "confvis/backends/analytic_maps.hpp"
#include "render_test_support.hpp"

namespace confvis {
namespace {

using test::imageOf;

constexpr int kWallPixels = 96;
constexpr double kLambda = 1.5;

RenderSettings stereoSettings(StereoRays rays) {
  RenderSettings settings;
  settings.mode = RenderMode::Conformal;
  settings.eyes = {Eye::Left, Eye::Right};
  settings.stereoRays = rays;
  settings.walls = {"front"};
  settings.resolutionScale = test::scaleFor(kWallPixels);
  return settings;
}

const RetargetMap& dilationMap() {
  static const RetargetMap map = ceilinglessDilationMap(kLambda, 256);
  return map;
}

// The checker-sphere plus a yellow square `distance` metres from c in the virtual direction
// shown at the centre of the front wall, facing c.
Scene sphereWithNearSquare(double distance, double size) {
  Scene scene = builtinScene("checker-sphere");
  scene.materials.push_back({"paint", glm::vec4(1, 1, 0, 1), -1});
  const glm::dvec3 centre = distance * stereographicDilation({0, 0, -1}, kLambda);
  scene.meshes.push_back(test::facingSquare(centre, glm::dvec3(0.0), size));
  scene.meshes.back().material = static_cast<int>(scene.materials.size()) - 1;
  return scene;
}

// Centroid of the yellow pixels (the square) in pixel units.
glm::dvec2 yellowCentroid(const ImageRGBA& image) {
  glm::dvec2 sum(0.0);
  std::size_t n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float* p = image.at(x, y);
      if (p[0] > 0.9f && p[1] > 0.9f && p[2] < 0.1f) {
        sum += glm::dvec2(x + 0.5, y + 0.5);
        ++n;
      }
    }
  EXPECT_GT(n, 20u) << "the square is not in view";
  return n ? sum / static_cast<double>(n) : glm::dvec2(0.0);
}

EmbreeBackend& nearSquareBackend() {
  static const std::unique_ptr<EmbreeBackend> backend = [] {
    auto b = std::make_unique<EmbreeBackend>();
    b->setScene(sphereWithNearSquare(0.4, 0.1));
    return b;
  }();
  return *backend;
}

TEST(EmbreeStereo, NearObjectShowsCrossedParallaxWithExactAndFastRays) {
  DisplayConfig config = test::shippedConfig("cave5");
  for (StereoRays rays : {StereoRays::Exact, StereoRays::Fast}) {
    SCOPED_TRACE(stereoRaysName(rays));
    const RenderResult result = nearSquareBackend().render(config, &dilationMap(),
                                                           stereoSettings(rays));
    const glm::dvec2 left = yellowCentroid(imageOf(result, "front", Eye::Left).image);
    const glm::dvec2 right = yellowCentroid(imageOf(result, "front", Eye::Right).image);
    // Near objects appear further right to the left eye; the offset is horizontal.
    EXPECT_GT(left.x - right.x, 2.0);
    EXPECT_LT(std::abs(left.y - right.y), 0.5);
  }
  // Broken: the eyes swapped (negative separation puts the left eye on the right).
  config.eyeSeparation = -config.eyeSeparation;
  const RenderResult swapped =
      nearSquareBackend().render(config, &dilationMap(), stereoSettings(StereoRays::Exact));
  EXPECT_LT(yellowCentroid(imageOf(swapped, "front", Eye::Left).image).x -
                yellowCentroid(imageOf(swapped, "front", Eye::Right).image).x,
            -2.0);
}

TEST(EmbreeStereo, ExactAndFastRaysAgreeOnTheCentreEye) {
  const DisplayConfig config = test::shippedConfig("cave5");
  RenderSettings exact = stereoSettings(StereoRays::Exact), fast = stereoSettings(StereoRays::Fast);
  exact.eyes = fast.eyes = {Eye::Center};
  exact.walls = fast.walls = {};
  const RenderResult a = nearSquareBackend().render(config, &dilationMap(), exact);
  const RenderResult b = nearSquareBackend().render(config, &dilationMap(), fast);
  ASSERT_EQ(a.images.size(), 5u);
  for (std::size_t i = 0; i < a.images.size(); ++i)
    EXPECT_EQ(a.images[i].image.pixels, b.images[i].image.pixels) << a.images[i].wall;
}

TEST(EmbreeStereo, CurvedRaysAreMarchedFinelyEnough) {
  const DisplayConfig config = test::shippedConfig("cave5");
  const Scene scene = sphereWithNearSquare(0.4, 0.1);
  auto render = [&](int segments) {
    EmbreeOptions options;
    options.curvedRaySegments = segments;
    EmbreeBackend backend(options);
    backend.setScene(scene);
    return backend.render(config, &dilationMap(), stereoSettings(StereoRays::Exact));
  };
  const RenderResult standard = render(EmbreeOptions{}.curvedRaySegments), fine = render(32),
                     coarse = render(1);
  for (Eye eye : {Eye::Left, Eye::Right}) {
    const ImageRGBA& reference = imageOf(fine, "front", eye).image;
    // The default marching matches 32 segments within a few edge pixels...
    EXPECT_TRUE(test::imagesMatch(imageOf(standard, "front", eye).image, reference, 0.02, 0.003));
    // ...whereas a single segment before the asymptote visibly bends the near square.
    const glm::dvec2 offset =
        yellowCentroid(imageOf(coarse, "front", eye).image) - yellowCentroid(reference);
    const glm::dvec2 standardOffset =
        yellowCentroid(imageOf(standard, "front", eye).image) - yellowCentroid(reference);
    EXPECT_LT(glm::length(standardOffset), 0.05);
    RecordProperty(std::string("coarse_offset_px_") + eyeName(eye), std::to_string(glm::length(offset)));
  }
}

// Exact and fast stereo rays differ by design: exact rays start at W(e) and leave along F of the
// physical ray's direction; fast rays start at e and aim at W(p). Measured here on the front
// wall of the 5-sided CAVE (analytic map, lambda 1.5) and reported as test properties.
TEST(EmbreeStereo, MeasuredDifferenceBetweenExactAndFastStereoRays) {
  const DisplayConfig config = test::shippedConfig("cave5");
  const RenderResult exact =
      nearSquareBackend().render(config, &dilationMap(), stereoSettings(StereoRays::Exact));
  const RenderResult fast =
      nearSquareBackend().render(config, &dilationMap(), stereoSettings(StereoRays::Fast));
  const double pixelsPerDegree = kWallPixels / 90.0;  // at the wall's centre
  for (Eye eye : {Eye::Left, Eye::Right}) {
    const ImageRGBA& a = imageOf(exact, "front", eye).image;
    const ImageRGBA& b = imageOf(fast, "front", eye).image;
    const test::ImageDiff diff = test::compareImages(a, b, 0.02);
    const double shift = glm::length(yellowCentroid(a) - yellowCentroid(b));
    const std::string suffix = std::string("_") + eyeName(eye);
    RecordProperty("differing_pixel_fraction" + suffix, std::to_string(diff.badFraction(a)));
    RecordProperty("near_square_shift_px" + suffix, std::to_string(shift));
    std::printf("exact vs fast, %s eye, %d px wall: %.2f %% of pixels differ, near square (0.4 m) "
                "moves %.2f px (%.2f deg)\n",
                eyeName(eye), kWallPixels, 100 * diff.badFraction(a), shift,
                shift / pixelsPerDegree);
    // Both stay close to each other: far content moves by well under a degree.
    EXPECT_LT(diff.badFraction(a), 0.25);
  }
  for (const RenderResult* result : {&exact, &fast}) {
    const double disparity = yellowCentroid(imageOf(*result, "front", Eye::Left).image).x -
                             yellowCentroid(imageOf(*result, "front", Eye::Right).image).x;
    const std::string mode = result == &exact ? "exact" : "fast";
    RecordProperty("near_square_disparity_px_" + mode, std::to_string(disparity));
    std::printf("%s stereo rays: near square disparity %.2f px (%.2f deg)\n", mode.c_str(),
                disparity, disparity / pixelsPerDegree);
  }
}

}  // namespace
}  // namespace confvis
