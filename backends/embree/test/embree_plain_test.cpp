// Plain (off-axis) renders of the Embree backend against closed forms: the checker-sphere's
// colour along every pixel's ray, stereo parallax of a near square, supersampled coverage,
// ambient occlusion, and the errors at the backend's boundary.
#include <gtest/gtest.h>

#include <map>
#include <memory>

#include "confvis/backends/embree/embree_device.hpp"
#include "confvis/base/error.hpp"
#include "render_test_support.hpp"

namespace confvis {
namespace {

using test::imageOf;
using test::scaleFor;
using test::checkerSphereBackend;

constexpr int kWallPixels = 48;

RenderSettings plainSettings(int pixels = kWallPixels) {
  RenderSettings settings;
  settings.mode = RenderMode::Plain;
  settings.resolutionScale = scaleFor(pixels);
  return settings;
}

double checkerMismatch(const ImageRGBA& image, const WallView& view, double scale,
                       const glm::dmat3& turn = glm::dmat3(1.0)) {
  return test::checkerMismatch(image, view, scale,
                               [&](const glm::dvec3& d) { return std::optional(turn * d); });
}

TEST(EmbreePlain, CheckerSphereShowsEachCubeFaceColourOnItsWall) {
  const DisplayConfig config = test::shippedConfig("cave6");
  const RenderSettings settings = plainSettings();
  const RenderResult result = checkerSphereBackend().render(config, nullptr, settings);
  ASSERT_EQ(result.images.size(), 6u);
  const std::map<std::string, glm::vec3> faceColour = {
      {"front", {0, 0, 1}}, {"back", {0, 0, 1}},  {"left", {1, 0, 0}},
      {"right", {1, 0, 0}}, {"floor", {0, 1, 0}}, {"ceiling", {0, 1, 0}}};
  for (const Wall& wall : config.walls) {
    SCOPED_TRACE(wall.name);
    const ImageRGBA& image = imageOf(result, wall.name, Eye::Center).image;
    ASSERT_EQ(image.width, kWallPixels);
    const WallView view = makeWallView(wall, config.reference);
    EXPECT_LT(checkerMismatch(image, view, settings.resolutionScale), 0.005);
    // Half the squares carry the face colour, the other half are white; nothing else.
    std::size_t face = 0, white = 0;
    for (std::size_t i = 0; i < image.pixelCount(); ++i) {
      const glm::vec3 c(image.pixels[4 * i], image.pixels[4 * i + 1], image.pixels[4 * i + 2]);
      if (glm::length(c - faceColour.at(wall.name)) < 0.05f) ++face;
      if (glm::length(c - glm::vec3(1.0f)) < 0.05f) ++white;
    }
    EXPECT_GT(face, image.pixelCount() * 4 / 10);
    EXPECT_GT(white, image.pixelCount() * 4 / 10);
  }
}

TEST(EmbreePlain, TurnedCameraFailsTheCheckerComparisonUnlessTheExpectationTurnsToo) {
  const DisplayConfig config = test::shippedConfig("cave6");
  RenderSettings settings = plainSettings();
  settings.walls = {"front"};
  settings.camera.yawDegrees = 90;  // the virtual world turned: the front wall shows the left
  const RenderResult result = checkerSphereBackend().render(config, nullptr, settings);
  const WallView view = makeWallView(config.wall("front"), config.reference);
  const ImageRGBA& image = result.images.at(0).image;
  EXPECT_GT(checkerMismatch(image, view, settings.resolutionScale), 0.3);
  EXPECT_LT(checkerMismatch(image, view, settings.resolutionScale, settings.camera.rotation()),
            0.005);
}

// A square 0.3 m in front of the viewer, 0.06 m wide, seen on the front wall 1.5 m away: each
// eye e sees its centre at x = e + (0 - e) * 1.5 / 0.3 = -4 e on the wall.
TEST(EmbreePlain, NearSquareShowsCrossedParallaxBetweenTheEyes) {
  const DisplayConfig config = test::shippedConfig("cave6");
  EmbreeBackend backend;
  backend.setScene(test::squareScene({0, 0, -0.3}, 0.06, {1, 1, 0}));
  RenderSettings settings = plainSettings(96);
  settings.walls = {"front"};
  settings.eyes = {Eye::Left, Eye::Right};
  const RenderResult result = backend.render(config, nullptr, settings);
  const glm::dvec2 left = test::coverageCentroid(imageOf(result, "front", Eye::Left).image);
  const glm::dvec2 right = test::coverageCentroid(imageOf(result, "front", Eye::Right).image);
  const double pixelsPerMetre = 96 / 3.0, half = config.eyeSeparation / 2;
  EXPECT_NEAR(left.x, (4 * half + 1.5) * pixelsPerMetre, 0.3);
  EXPECT_NEAR(right.x, (-4 * half + 1.5) * pixelsPerMetre, 0.3);
  EXPECT_NEAR(left.y, 48, 0.3);
  EXPECT_NEAR(right.y, 48, 0.3);
  EXPECT_GT(left.x, right.x);  // crossed disparity: the left eye sees a near object further right
}

TEST(EmbreePlain, SupersamplingConvergesToTheProjectedArea) {
  const DisplayConfig config = test::shippedConfig("cave6");
  EmbreeBackend backend;
  // 0.1 m square at 0.7 m: 0.2143 m on the wall, 6.86 px of 96: edges fall inside pixels.
  backend.setScene(test::squareScene({0.01, 0.02, -0.7}, 0.1, {1, 1, 1}));
  const double side = 0.1 * 1.5 / 0.7 * 96 / 3.0;
  auto coverage = [&](int spp) {
    RenderSettings settings = plainSettings(96);
    settings.walls = {"front"};
    settings.samplesPerPixel = spp;
    const ImageRGBA image = backend.render(config, nullptr, settings).images.at(0).image;
    double sum = 0;
    for (std::size_t i = 0; i < image.pixelCount(); ++i) sum += image.pixels[4 * i + 3];
    return sum;
  };
  EXPECT_NEAR(coverage(16), side * side, 0.6);
  EXPECT_NEAR(coverage(7), side * side, 1.5);  // a non-square count: Latin hypercube
  EXPECT_NEAR(coverage(1), side * side, 8.0);  // one central sample: whole pixels only
}

TEST(EmbreePlain, AmbientOcclusionDarkensOnlyNearAnInnerCorner) {
  const DisplayConfig config = test::shippedConfig("cave6");
  // The front wall's view of an inner corner: a floor-like plane y = -1 meeting a back plane
  // z = -3 along the line y = -1, z = -3.
  Scene scene;
  scene.name = "corner";
  Mesh floor, back;
  floor.positions = {{-5, -1, 0}, {5, -1, 0}, {-5, -1, -3}, {5, -1, -3}};
  floor.triangles = {{0, 1, 3}, {0, 3, 2}};
  back.positions = {{-5, -1, -3}, {5, -1, -3}, {-5, 4, -3}, {5, 4, -3}};
  back.triangles = {{0, 1, 3}, {0, 3, 2}};
  scene.meshes = {floor, back};
  EmbreeOptions options;
  options.ambientOcclusionDistance = 0.5;
  options.ambientOcclusionSamples = 16;
  EmbreeBackend backend(options);
  backend.setScene(scene);
  RenderSettings settings = plainSettings(64);
  settings.walls = {"front"};
  const ImageRGBA lit = backend.render(config, nullptr, settings).images.at(0).image;
  settings.ambientOcclusion = true;
  const ImageRGBA occluded = backend.render(config, nullptr, settings).images.at(0).image;
  // The crease y = -1 at z = -3 appears on the wall at y = -0.5 (row 42.7 of 64): just above
  // it (back plane) and below it (floor) occlusion darkens; far from it nothing changes.
  const WallView view = makeWallView(config.wall("front"), config.reference);
  double nearSum = 0, nearLitSum = 0;
  int farChanged = 0, farCount = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 8; x < 56; ++x) {
      const glm::dvec3 d = view.rayDirection((x + 0.5) * 30, (y + 0.5) * 30);
      // The ray meets the floor plane before z = -3 or else the back plane.
      const double floorZ = d.y < 0 ? d.z / -d.y : -1e9;  // z where y = -1
      const double distanceToCrease = floorZ >= -3.0 ? floorZ + 3.0 : 3.0 * d.y / -d.z + 1.0;
      const float a = occluded.at(x, y)[0], b = lit.at(x, y)[0];
      if (std::abs(distanceToCrease) > 0.6) {
        ++farCount;
        if (std::abs(a - b) > 1e-5f) ++farChanged;
      } else if (std::abs(distanceToCrease) < 0.1) {
        nearSum += a;
        nearLitSum += b;
      }
    }
  ASSERT_GT(farCount, 100);
  EXPECT_EQ(farChanged, 0);
  ASSERT_GT(nearLitSum, 0.0);
  EXPECT_LT(nearSum, 0.8 * nearLitSum);
}

TEST(EmbreePlain, BadRequestsGiveOneClearError) {
  const DisplayConfig config = test::shippedConfig("cave6");
  EmbreeBackend fresh;
  try {
    fresh.render(config, nullptr, plainSettings());
    FAIL() << "rendering without a scene must fail";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("setScene"), std::string::npos) << e.what();
  }
  RenderSettings settings = plainSettings();
  settings.walls = {"front", "attic"};
  try {
    checkerSphereBackend().render(config, nullptr, settings);
    FAIL() << "an unknown wall must fail";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput);
    EXPECT_NE(std::string(e.what()).find("attic"), std::string::npos) << e.what();
  }
  settings = plainSettings();
  settings.mode = RenderMode::Conformal;
  EXPECT_THROW(checkerSphereBackend().render(config, nullptr, settings), Error);
  settings = plainSettings();
  settings.samplesPerPixel = 0;
  EXPECT_THROW(checkerSphereBackend().render(config, nullptr, settings), Error);
  settings = plainSettings();
  settings.head.position = {0, 0, -2};  // outside the CAVE, behind the front wall
  try {
    checkerSphereBackend().render(config, nullptr, settings);
    FAIL() << "an eye behind a wall must fail";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("front"), std::string::npos) << e.what();
  }
  Scene empty;
  empty.name = "empty";
  EXPECT_THROW(fresh.setScene(empty), Error);
}

TEST(EmbreeDeviceErrors, EmbreeErrorsBecomeConfvisErrorsNamingTheOperation) {
  EmbreeDevice device;
  device.check("nothing");  // no error pending: no throw
  RTCGeometry geometry = rtcNewGeometry(device.handle(), static_cast<RTCGeometryType>(12345));
  if (geometry) rtcReleaseGeometry(geometry);
  try {
    device.check("creating a bogus geometry");
    FAIL() << "Embree's error must surface";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("creating a bogus geometry"), std::string::npos)
        << e.what();
  }
  device.check("after the error was reported");  // reported once, then cleared
  EXPECT_THROW(EmbreeDevice("verbose=abc"), Error);  // Embree rejects this config
}

}  // namespace
}  // namespace confvis
