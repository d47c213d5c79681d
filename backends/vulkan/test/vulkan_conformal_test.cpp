// Conformal rendering against closed forms: identity map == plain; a rotation map shows the
// neighbouring wall's plain image; an azimuth squeeze with a cut matches T_ray exactly, leaves
// the back empty (no triangle smeared across the cut) and needs its tessellation.
#include <gtest/gtest.h>

#include "confvis/engine/builtin_scenes.hpp"
#include "vulkan_test_maps.hpp"
#include "vulkan_test_support.hpp"

namespace confvis {
namespace {

using test::compareAnalytic;
using test::imageOf;

constexpr int kWallPixels = 64;
constexpr int kMapResolution = 64;

// The checker-sphere with one quad per cube face: the cube seen from its centre. Its checker
// squares are exact (uv is linear on each flat face, as gnomonic coordinates are) and Lambert
// from the centre is exactly 1 (vertex normals interpolate to the radial direction), so every
// pixel has a closed form; its 90-degree triangles bend visibly under a non-trivial warp.
Scene checkerCube() {
  BuiltinSceneOptions options;
  options.subdivision = 1;
  options.texelsPerSquare = 64;  // texture edges sharper than a pixel, even magnified
  return builtinScene("checker-sphere", options);
}

RenderSettings settingsFor(const DisplayConfig& config, RenderMode mode) {
  RenderSettings settings;
  settings.mode = mode;
  settings.resolutionScale = test::scaleFor(config, kWallPixels);
  return settings;
}

std::optional<glm::vec3> sphereColor(glm::dvec3 d) { return checkerSphereColor(d); }

TEST(VulkanConformal, IdentityMapOnSixWallsEqualsPlain) {
  test::ValidatedBackend vk;
  const DisplayConfig config = test::loadConfig("cave6");
  vk->setScene(checkerCube());
  const RetargetMap identity = RetargetMap::identity(kMapResolution);
  const RenderResult plain = vk->render(config, nullptr, settingsFor(config, RenderMode::Plain));
  const RenderResult conformal =
      vk->render(config, &identity, settingsFor(config, RenderMode::Conformal));
  ASSERT_EQ(conformal.images.size(), 6u);
  for (std::size_t i = 0; i < 6; ++i) {
    SCOPED_TRACE(config.walls[i].name);
    const test::PixelComparison c =
        test::comparePixels(conformal.images[i].image, plain.images[i].image, 0.02f);
    EXPECT_LE(c.badFraction(), 0.005) << c.bad << " pixels differ, max " << c.maxError;
    const test::AnalyticComparison a = compareAnalytic(
        conformal.images[i].image, config.walls[i], glm::dvec3(0.0), sphereColor, 0.02f);
    EXPECT_GT(a.unambiguous, a.pixels * 6 / 10);
    EXPECT_LE(a.bad, a.unambiguous / 200);
  }
  test::expectNoValidationMessages(vk);
}

TEST(VulkanConformal, RotationMapShowsThePlainImageOfTheNeighbouringWall) {
  // T_geom = rotation by 90 degrees about +y: the virtual direction shown on physical wall P is
  // R^T dir(P), so each side wall shows what its right-hand neighbour shows in plain mode, pixel
  // for pixel (the cube's walls are rotated copies of each other).
  test::ValidatedBackend vk;
  const DisplayConfig config = test::loadConfig("cave6");
  vk->setScene(builtinScene("checker-sphere"));
  const RetargetMap rotation = test::rotationMap(kMapResolution, 90.0);
  const RenderResult plain = vk->render(config, nullptr, settingsFor(config, RenderMode::Plain));
  const RenderResult conformal =
      vk->render(config, &rotation, settingsFor(config, RenderMode::Conformal));
  const std::vector<std::pair<std::string, std::string>> shows = {
      {"front", "right"}, {"right", "back"}, {"back", "left"}, {"left", "front"}};
  for (const auto& [physical, virtualWall] : shows) {
    SCOPED_TRACE(physical + " shows " + virtualWall);
    const test::PixelComparison c = test::comparePixels(
        imageOf(conformal, physical).image, imageOf(plain, virtualWall).image, 0.02f);
    EXPECT_LE(c.badFraction(), 0.005) << c.bad << " pixels differ, max " << c.maxError;
    // ... and not what it shows in plain mode (the comparison can fail).
    EXPECT_GT(test::comparePixels(imageOf(conformal, physical).image,
                                  imageOf(plain, physical).image, 0.02f)
                  .badFraction(),
              0.2);
  }
  test::expectNoValidationMessages(vk);
}

TEST(VulkanConformal, AzimuthSqueezeMatchesTheClosedFormAndSmearsNothingAcrossTheCut) {
  const DisplayConfig config = test::loadConfig("cave6");
  const RetargetMap squeeze = test::azimuthSqueezeMap(kMapResolution);
  const test::DirectionColor expected = [](glm::dvec3 d) -> std::optional<glm::vec3> {
    const auto v = test::squeezeToVirtual(glm::normalize(d));
    if (!v) return std::nullopt;
    return checkerSphereColor(*v);
  };
  const auto render = [&](bool tessellate) {
    VulkanOptions options;
    options.tessellate = tessellate;
    options.splitWideTriangles = tessellate;  // untessellated: the 90-degree triangles drawn whole
    test::ValidatedBackend vk(options);
    vk->setScene(checkerCube());
    RenderResult result = vk->render(config, &squeeze, settingsFor(config, RenderMode::Conformal));
    test::expectNoValidationMessages(vk);
    return result;
  };
  const RenderResult result = render(true);
  for (const WallImage& image : result.images) {
    SCOPED_TRACE(image.wall);
    const test::AnalyticComparison a =
        compareAnalytic(image.image, config.wall(image.wall), glm::dvec3(0.0), expected, 0.02f);
    EXPECT_GT(a.unambiguous, a.pixels * 6 / 10);
    EXPECT_LE(a.bad, a.unambiguous / 100) << a.bad << " of " << a.unambiguous << " pixels off";
  }
  // Nothing lands behind the viewer: the whole virtual sphere went to the front half. (Triangles
  // straddling the cut, their corners thrown to opposite side walls, must be split along it or
  // dropped: drawn whole, they would cut across the front wall and fail the comparison above.)
  EXPECT_EQ(test::drawnPixels(imageOf(result, "back").image), 0u);

  // Without tessellation the 90-degree triangles are drawn flat between their warped corners.
  const RenderResult flat = render(false);
  std::size_t bad = 0, unambiguous = 0;
  for (const WallImage& image : flat.images) {
    const test::AnalyticComparison a =
        compareAnalytic(image.image, config.wall(image.wall), glm::dvec3(0.0), expected, 0.02f);
    bad += a.bad;
    unambiguous += a.unambiguous;
  }
  EXPECT_GT(bad, unambiguous / 20) << "an untessellated warp should be visibly wrong";
}

TEST(VulkanConformal, ConformalZoomMatchesTheClosedForm) {
  // A smooth conformal map (Moebius dilation, no cut) bends the cube's 90-degree edges into arcs:
  // every pixel shows the cube's colour along T_ray of its direction, and skipping the
  // tessellation fails visibly.
  const DisplayConfig config = test::loadConfig("cave5");
  const RetargetMap zoom = test::zoomMap(kMapResolution, 2.0);
  const test::DirectionColor expected = [](glm::dvec3 d) -> std::optional<glm::vec3> {
    return checkerSphereColor(test::scaleStereographic(glm::normalize(d), 2.0));
  };
  for (bool tessellate : {true, false}) {
    VulkanOptions options;
    options.tessellate = tessellate;
    options.splitWideTriangles = tessellate;  // untessellated: the 90-degree triangles drawn whole
    test::ValidatedBackend vk(options);
    vk->setScene(checkerCube());
    const RenderResult result =
        vk->render(config, &zoom, settingsFor(config, RenderMode::Conformal));
    std::size_t bad = 0, unambiguous = 0;
    for (const WallImage& image : result.images) {
      const test::AnalyticComparison a = compareAnalytic(image.image, config.wall(image.wall),
                                                         glm::dvec3(0.0), expected, 0.02f);
      bad += a.bad;
      unambiguous += a.unambiguous;
    }
    EXPECT_GT(unambiguous, 5u * 64 * 64 * 6 / 10);
    if (tessellate)
      EXPECT_LE(bad, unambiguous / 100) << bad << " of " << unambiguous << " pixels off";
    else
      EXPECT_GT(bad, unambiguous / 20) << "an untessellated warp should be visibly wrong";
    test::expectNoValidationMessages(vk);
  }
}

TEST(VulkanConformal, TrianglesBentByTwoSegmentsAreDrawnInFlatPiecesThatMatchTheClosedForm) {
  // A sphere under the smooth zoom map: most bent triangles need two segments an edge and
  // are drawn as flat pieces between their corners and edge midpoints (no tessellation); no
  // triangle needs the geometry shader (no cut, no rim). Pieces with a wrong midpoint or corner
  // leave holes or smears that the closed form catches.
  test::ValidatedBackend vk;
  const DisplayConfig config = test::loadConfig("cave5");
  BuiltinSceneOptions sceneOptions;
  sceneOptions.subdivision = 8;       // 768 triangles of about 11 degrees
  sceneOptions.texelsPerSquare = 64;  // texture edges sharper than a pixel
  const Scene scene = builtinScene("checker-sphere", sceneOptions);
  vk->setScene(scene);
  const RetargetMap zoom = test::zoomMap(256, 2.0);
  RenderSettings settings = settingsFor(config, RenderMode::Conformal);
  settings.resolutionScale = test::scaleFor(config, 96);
  const RenderResult result = vk->render(config, &zoom, settings);
  const VulkanConformalStats& prepass = result.stats.vulkan.value().conformalPrepass.value();
  const auto flat = prepass.trianglesDrawnFlat;
  const auto tessellated = prepass.trianglesTessellated;
  // Split triangles count each piece (2-4): measured 1104 drawn flat (1524 when every wall
  // point had the bound of the walls' smallest pixel), none tessellated.
  EXPECT_GT(flat, scene.triangleCount() * 5 / 4) << "pieces of split triangles";
  EXPECT_LT(tessellated, scene.triangleCount() / 10);
  EXPECT_EQ(prepass.trianglesThroughGeometryShader, 0u);
  for (const WallImage& image : result.images) {
    SCOPED_TRACE(image.wall);
    const test::AnalyticComparison a = compareAnalytic(
        image.image, config.wall(image.wall), glm::dvec3(0.0),
        [](glm::dvec3 d) -> std::optional<glm::vec3> {
          return checkerSphereColor(test::scaleStereographic(glm::normalize(d), 2.0));
        },
        0.05f);
    EXPECT_GT(a.unambiguous, a.pixels / 2);
    EXPECT_LE(a.bad, a.unambiguous / 100) << a.bad << " of " << a.unambiguous << " pixels off";
  }
  test::expectNoValidationMessages(vk);
}

TEST(VulkanConformal, HeavilyTessellatedDrawsStayCorrect) {
  // A fine sphere under the squeeze at 96 pixels a wall with an eighth-pixel error bound:
  // thousands of patches subdivided up to level 64, each list in one draw. Lavapipe restarts
  // gl_PrimitiveID within large indexed tessellation draws (patches then read other patches' edge
  // levels: cracks, and stray triangles covering whole walls through the geometry shader), so
  // warp.vert finds the patch's slot from gl_VertexIndex of a non-indexed draw; the image must
  // match the closed form. Without validation layers: with them, lavapipe happened to draw even
  // the broken case correctly.
  VulkanOptions options;
  options.device = test::testDevice();
  options.tessellationErrorPixels = 0.125;
  const std::unique_ptr<RenderBackend> vk = makeVulkanBackend(options);
  const DisplayConfig config = test::loadConfig("cave5");
  BuiltinSceneOptions sceneOptions;
  sceneOptions.subdivision = 41;      // 20k triangles
  sceneOptions.texelsPerSquare = 64;  // texture edges sharper than a pixel
  vk->setScene(builtinScene("checker-sphere", sceneOptions));
  const RetargetMap squeeze = test::azimuthSqueezeMap(256);
  RenderSettings settings = settingsFor(config, RenderMode::Conformal);
  settings.resolutionScale = test::scaleFor(config, 96);
  const RenderResult result = vk->render(config, &squeeze, settings);
  for (const WallImage& image : result.images) {
    SCOPED_TRACE(image.wall);
    const test::AnalyticComparison a =
        compareAnalytic(image.image, config.wall(image.wall), glm::dvec3(0.0),
                        [](glm::dvec3 d) -> std::optional<glm::vec3> {
                          const auto v = test::squeezeToVirtual(glm::normalize(d));
                          if (!v) return std::nullopt;
                          return checkerSphereColor(*v);
                        },
                        0.05f);
    EXPECT_GT(a.unambiguous, a.pixels / 2);
    EXPECT_LE(a.bad, a.unambiguous / 100) << a.bad << " of " << a.unambiguous << " pixels off";
  }
}

}  // namespace
}  // namespace confvis
