// Off-axis wall views (Kooima's generalized perspective projection) against hand-computed
// frusta, and eye placement from a head pose.
#include "confvis/engine/view.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>

#include <glm/gtc/quaternion.hpp>

#include "confvis/base/error.hpp"
#include "display_test_support.hpp"

using namespace confvis;
using confvis::testing::shippedConfig;
using confvis::testing::vecNear;

namespace {

struct Extents {
  double left, right, bottom, top, distance;
};

void expectExtents(const WallView& v, const Extents& e) {
  SCOPED_TRACE(v.wall->name);
  EXPECT_NEAR(v.left, e.left, 1e-12);
  EXPECT_NEAR(v.right, e.right, 1e-12);
  EXPECT_NEAR(v.bottom, e.bottom, 1e-12);
  EXPECT_NEAR(v.top, e.top, 1e-12);
  EXPECT_NEAR(v.nearDistance, e.distance, 1e-12);
}

// Normalised device coordinates of a world point.
glm::dvec3 ndc(const glm::dmat4& projection, const WallView& v, const glm::dvec3& p) {
  const glm::dvec4 clip = projection * v.view * glm::dvec4(p, 1.0);
  return glm::dvec3(clip) / clip.w;
}

// Clip-space x and y (z dropped) of a world point.
glm::dvec3 clipXY(const glm::dmat4& projection, const WallView& v, const glm::dvec3& p) {
  const glm::dvec3 n = ndc(projection, v, p);
  return {n.x, n.y, 0.0};
}

}  // namespace

TEST(ViewFrustum, CentredEyeSeesEveryCaveWallSymmetrically) {
  const DisplayConfig cave = shippedConfig("cave6.json");
  for (const WallView& v : makeViews(cave, HeadPose{}, Eye::Center))
    expectExtents(v, {-1.5, 1.5, -1.5, 1.5, 1.5});  // extents equal +-distance: 90 degrees
}

TEST(ViewFrustum, EyeHalfAMetreRightGivesTheHandComputedAsymmetricFrusta) {
  const DisplayConfig cave = shippedConfig("cave6.json");
  const glm::dvec3 eye{0.5, 0.0, 0.0};
  // Wall right axes: front +x, back -x, right +z, left -z, floor/ceiling +x.
  const std::map<std::string, Extents> expected{
      {"front", {-2.0, 1.0, -1.5, 1.5, 1.5}}, {"back", {-1.0, 2.0, -1.5, 1.5, 1.5}},
      {"right", {-1.5, 1.5, -1.5, 1.5, 1.0}}, {"left", {-1.5, 1.5, -1.5, 1.5, 2.0}},
      {"floor", {-2.0, 1.0, -1.5, 1.5, 1.5}}, {"ceiling", {-2.0, 1.0, -1.5, 1.5, 1.5}}};
  for (const auto& [name, extents] : expected)
    expectExtents(makeWallView(cave.wall(name), eye), extents);
}

TEST(ViewFrustum, ViewMatrixPutsTheEyeAtTheOriginAndTheWallAtMinusDistance) {
  const DisplayConfig cave = shippedConfig("cave6.json");
  const Wall& right = cave.wall("right");
  const WallView v = makeWallView(right, {0.5, 0.2, -0.3});
  EXPECT_TRUE(vecNear(glm::dvec3(v.view * glm::dvec4(0.5, 0.2, -0.3, 1.0)), {0, 0, 0}));
  EXPECT_TRUE(vecNear(glm::dvec3(v.view * glm::dvec4(right.lowerLeft, 1.0)),
                      {v.left, v.bottom, -v.nearDistance}));
  EXPECT_TRUE(vecNear(glm::dvec3(v.view * glm::dvec4(right.upperRight(), 1.0)),
                      {v.right, v.top, -v.nearDistance}));
}

TEST(ViewProjection, WallCornersLandOnTheClipBorderInGLAndVulkan) {
  const DisplayConfig cave = shippedConfig("cave5.json");
  const double near = 0.1, far = 50.0;
  for (const WallView& v : makeViews(cave, HeadPose{{0.3, -0.2, 0.4}}, Eye::Center)) {
    SCOPED_TRACE(v.wall->name);
    const Wall& w = *v.wall;
    const glm::dmat4 gl = v.projectionGL(near, far), vk = v.projectionVulkan(near, far);
    EXPECT_TRUE(vecNear(clipXY(gl, v, w.lowerLeft), {-1, -1, 0}, 1e-12));
    EXPECT_TRUE(vecNear(clipXY(gl, v, w.upperRight()), {1, 1, 0}, 1e-12));
    EXPECT_TRUE(vecNear(clipXY(gl, v, w.upperLeft), {-1, 1, 0}, 1e-12));
    // Vulkan: y points down, so the upper edge is at -1.
    EXPECT_TRUE(vecNear(clipXY(vk, v, w.upperLeft), {-1, -1, 0}, 1e-12));
    EXPECT_TRUE(vecNear(clipXY(vk, v, w.lowerRight), {1, 1, 0}, 1e-12));
    // Depth: the near and far planes map to -1/1 (GL) and 0/1 (Vulkan).
    const glm::dvec3 eye = v.eye_position;
    const glm::dvec3 toCentre = w.pointAt(0.5, 0.5) - eye;
    const glm::dvec3 onNear = eye + toCentre * (near / v.nearDistance);
    const glm::dvec3 onFar = eye + toCentre * (far / v.nearDistance);
    EXPECT_NEAR(ndc(gl, v, onNear).z, -1.0, 1e-9);
    EXPECT_NEAR(ndc(gl, v, onFar).z, 1.0, 1e-9);
    EXPECT_NEAR(ndc(vk, v, onNear).z, 0.0, 1e-9);
    EXPECT_NEAR(ndc(vk, v, onFar).z, 1.0, 1e-9);
  }
}

// Reverse-Z, far plane at infinity: the same x and y as projectionVulkan, depth 1 on the near
// plane, near / distance beyond it, and still ordered a part in a million apart at 1 km and 1 mm.
TEST(ViewProjection, ReverseZKeepsVulkansXYAndOrdersDepthAtAnyDistance) {
  const DisplayConfig cave = shippedConfig("cave5.json");
  for (const WallView& v : makeViews(cave, HeadPose{{0.3, -0.2, 0.4}}, Eye::Center)) {
    SCOPED_TRACE(v.wall->name);
    const Wall& w = *v.wall;
    const double near = 1e-4;
    const glm::dmat4 vk = v.projectionVulkan(0.1, 50.0), reverse = v.projectionVulkanReverseZ(near);
    for (const glm::dvec3& corner : {w.lowerLeft, w.upperLeft, w.lowerRight, w.upperRight()})
      EXPECT_TRUE(vecNear(clipXY(reverse, v, corner), clipXY(vk, v, corner), 1e-12));
    const glm::dvec3 eye = v.eye_position;
    const glm::dvec3 toCentre = w.pointAt(0.3, 0.6) - eye;
    const auto at = [&](double distance) { return eye + toCentre * (distance / v.nearDistance); };
    EXPECT_NEAR(ndc(reverse, v, at(near)).z, 1.0, 1e-9);
    EXPECT_NEAR(ndc(reverse, v, at(2.0 * near)).z, 0.5, 1e-9);
    for (double distance : {1e-3, 1.0, 1e3}) {
      // As the D32 float depth buffer holds it.
      const auto depth = [&](double d) { return static_cast<float>(ndc(reverse, v, at(d)).z); };
      EXPECT_GT(depth(distance), depth(distance * (1.0 + 1e-5))) << distance;
    }
  }
  EXPECT_THROW((void)makeViews(cave, HeadPose{}, Eye::Center)[0].projectionVulkanReverseZ(0.0),
               Error);
}

TEST(ViewProjection, RejectsAnInvalidDepthRange) {
  const WallView v = makeWallView(shippedConfig("cave3.json").wall("front"), {0, 0, 0});
  EXPECT_THROW((void)v.projectionGL(0.0, 10.0), Error);
  EXPECT_THROW((void)v.projectionVulkan(1.0, 0.5), Error);
}

TEST(ViewRay, PixelRaysHitTheMatchingWallPoints) {
  const DisplayConfig cave = shippedConfig("cave6.json");
  const Wall& floor = cave.wall("floor");
  const glm::dvec3 eye{0.4, 0.1, -0.7};
  const WallView v = makeWallView(floor, eye);
  EXPECT_TRUE(vecNear(eye + v.rayDirection(floor.width / 2.0, floor.height / 2.0),
                      floor.pointAt(0.5, 0.5), 1e-12));
  EXPECT_TRUE(vecNear(eye + v.rayDirection(0, 0), floor.upperLeft, 1e-12));
  EXPECT_TRUE(vecNear(eye + v.rayDirection(floor.width, floor.height), floor.lowerRight, 1e-12));
  EXPECT_TRUE(vecNear(eye + v.rayDirection(17.5, 1000.5), floor.pixelCenter(17, 1000), 1e-12));
}

TEST(ViewRay, AngledMonitorFrustumMatchesTheClosedForm) {
  const DisplayConfig md = shippedConfig("md230x6.json");
  const Wall& wall = md.wall("top-right");
  const Wall lit = wall.litRectangle();
  // The column is turned by theta about +y toward the viewer: right = (cos, 0, sin).
  const double theta = std::atan2(wall.right().z, wall.right().x);
  EXPECT_NEAR(theta * 180.0 / std::numbers::pi, 35.0, 1e-3);
  const double hinge = wall.lowerLeft.x, depth = -wall.lowerLeft.z, b = wall.bezel.left;
  const WallView v = makeWallView(wall, md.reference);
  // Distance from the eye to the turned plane, and extents from the foot of the perpendicular.
  EXPECT_NEAR(v.nearDistance, hinge * std::sin(theta) + depth * std::cos(theta), 1e-9);
  EXPECT_NEAR(v.left, hinge * std::cos(theta) - depth * std::sin(theta) + b, 1e-9);
  EXPECT_NEAR(v.right - v.left, lit.widthMetres(), 1e-12);
  EXPECT_NEAR(v.bottom, b, 1e-12);  // lower edge at eye height, plus the bezel
  EXPECT_NEAR(v.top, wall.heightMetres() - wall.bezel.top, 1e-12);
  // The frustum spans the lit area, not the bezel.
  EXPECT_TRUE(vecNear(md.reference + v.rayDirection(0, 0), lit.upperLeft, 1e-12));
  EXPECT_TRUE(vecNear(md.reference + v.rayDirection(960, 540), lit.pointAt(0.5, 0.5), 1e-12));
  const glm::dvec3 corner = ndc(v.projectionGL(0.05, 10.0), v, lit.upperRight());
  EXPECT_NEAR(corner.x, 1.0, 1e-12);
  EXPECT_NEAR(corner.y, 1.0, 1e-12);
}

TEST(ViewErrors, EyeOnOrBehindAWallPlaneIsNamed) {
  const DisplayConfig cave = shippedConfig("cave4.json");
  for (const glm::dvec3& eye : {glm::dvec3(0, 0, -1.5), glm::dvec3(0.2, 0.1, -2.0)}) {
    try {
      (void)makeViews(cave, HeadPose{eye}, Eye::Center);
      ADD_FAILURE() << "expected an Error";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::InvalidInput);
      EXPECT_NE(std::string(e.what()).find("wall 'front'"), std::string::npos) << e.what();
    }
  }
}

TEST(Viewer, EyesSitAlongTheHeadsRightAxis) {
  HeadPose head{{0.0, 1.7, 0.0}};  // default orientation: identity
  EXPECT_EQ(head.orientation, glm::dquat(1.0, 0.0, 0.0, 0.0));
  EXPECT_TRUE(vecNear(eyePosition(head, Eye::Left, 0.064), {-0.032, 1.7, 0}));
  EXPECT_TRUE(vecNear(eyePosition(head, Eye::Right, 0.064), {0.032, 1.7, 0}));
  EXPECT_TRUE(vecNear(eyePosition(head, Eye::Center, 0.064), {0, 1.7, 0}));
  // Turned 90 degrees left (looking down -x): the right axis is -z.
  head.orientation = glm::angleAxis(std::numbers::pi / 2, glm::dvec3(0, 1, 0));
  EXPECT_TRUE(vecNear(eyePosition(head, Eye::Right, 0.064), {0, 1.7, -0.032}, 1e-15));
  EXPECT_TRUE(vecNear(eyePosition(head, Eye::Left, 0.064), {0, 1.7, 0.032}, 1e-15));
}

TEST(Viewer, MakeViewsGivesOneViewPerWallFromTheChosenEye) {
  const DisplayConfig cave = shippedConfig("cave5.json");
  const HeadPose head{{0.1, 0.0, 0.2}, glm::angleAxis(0.3, glm::dvec3(0, 1, 0))};
  const std::vector<WallView> views = makeViews(cave, head, Eye::Left);
  ASSERT_EQ(views.size(), cave.walls.size());
  for (std::size_t i = 0; i < views.size(); ++i) {
    EXPECT_EQ(views[i].wall, &cave.walls[i]);
    EXPECT_EQ(views[i].eye, Eye::Left);
    EXPECT_TRUE(vecNear(views[i].eye_position, eyePosition(head, Eye::Left, cave.eyeSeparation)));
  }
  // The left eye is nearer the left wall than the head centre is.
  const WallView centre = makeWallView(cave.wall("left"), head.position);
  EXPECT_LT(views[1].nearDistance, centre.nearDistance);
}
