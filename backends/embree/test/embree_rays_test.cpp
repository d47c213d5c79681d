// The pieces under the Embree backend's camera rays: the curved-ray march against closed forms
// and the stratified sample patterns.
#include <gtest/gtest.h>

#include <set>

#include "../src/camera_rays.hpp"
#include "../src/sampling.hpp"
#include "confvis/backends/analytic_maps.hpp"
#include "render_test_support.hpp"

namespace confvis::embree {
namespace {

// Distance of p from the line, as an angle seen from c = 0: the map itself is only a bilinear
// cube map (renormalised directions are off by ~1e-5 rad at 128 texels), so positions far from c
// carry proportionally larger errors.
double angleFromLine(const glm::dvec3& p, const glm::dvec3& origin, const glm::dvec3& unit) {
  const glm::dvec3 d = p - origin;
  return glm::length(d - glm::dot(d, unit) * unit) / std::max(glm::length(p), 1e-3);
}

TEST(CurvedRay, IdentityMapKeepsThePhysicalRayStraight) {
  const RetargetMap identity = RetargetMap::identity(128);
  const ConformalWarp warp(identity);
  const glm::dvec3 eye(-0.032, 0.01, 0.0), u = glm::normalize(glm::dvec3(0.3, 0.2, -1.0));
  std::array<glm::dvec3, kMaxCurvedSegments + 2> vertices;
  glm::dvec3 tail;
  const int count = curvedRay(warp, eye, u, 12, vertices.data(), tail);
  ASSERT_EQ(count, 13);
  for (int i = 0; i < count; ++i) EXPECT_LT(angleFromLine(vertices[i], eye, u), 3e-5) << i;
  for (int i = 1; i < count; ++i)  // ordered along the ray, away from the eye
    EXPECT_GT(glm::dot(vertices[i] - vertices[i - 1], u), 0.0) << i;
  EXPECT_NEAR(glm::dot(tail, u), 1.0, 1e-6);
  EXPECT_NEAR(glm::length(vertices[0] - eye), 0.0, 1e-6);
}

// W is linear for a rotation map: the curve is the rotated line, starting at W(e) = R e.
TEST(CurvedRay, RotationMapGivesTheRotatedLine) {
  VirtualCamera turn;
  turn.yawDegrees = 90;
  const glm::dmat3 r = turn.rotation();
  const RetargetMap map = rotationMap(r, 128);
  const ConformalWarp warp(map);
  const glm::dvec3 eye(0.032, 0.0, 0.0), u = glm::normalize(glm::dvec3(-0.5, 0.1, -1.0));
  std::array<glm::dvec3, kMaxCurvedSegments + 2> vertices;
  glm::dvec3 tail;
  const int count = curvedRay(warp, eye, u, 8, vertices.data(), tail);
  for (int i = 0; i < count; ++i) EXPECT_LT(angleFromLine(vertices[i], r * eye, r * u), 3e-5) << i;
  EXPECT_NEAR(glm::dot(tail, r * u), 1.0, 1e-6);
}

TEST(CurvedRay, RaysAlongALineThroughTheReferencePoint) {
  const RetargetMap map = ceilinglessDilationMap(1.5, 128);
  const ConformalWarp warp(map);
  std::array<glm::dvec3, kMaxCurvedSegments + 2> vertices;
  glm::dvec3 tail;
  // Away from c: one straight half-line from W(e) along F(u).
  const glm::dvec3 u = glm::normalize(glm::dvec3(0.2, -0.3, -1.0));
  EXPECT_EQ(curvedRay(warp, 0.05 * u, u, 12, vertices.data(), tail), 1);
  EXPECT_LT(glm::length(vertices[0] - 0.05 * warp.direction(u)), 1e-9);
  // Through c: W(e), then c, then F(u).
  EXPECT_EQ(curvedRay(warp, -0.05 * u, u, 12, vertices.data(), tail), 2);
  EXPECT_LT(glm::length(vertices[1]), 1e-12);
  EXPECT_LT(glm::length(tail - warp.direction(u)), 1e-9);
}

TEST(StratifiedSamples, EveryStratumOnceInsideThePixel) {
  for (int count : {4, 9, 16, 5, 7, 12}) {
    std::set<int> columns, rows, cells;
    const int side = static_cast<int>(std::lround(std::sqrt(count)));
    const bool grid = side * side == count;
    for (int i = 0; i < count; ++i) {
      const glm::dvec2 s = stratifiedSample(i, count, 12345u);
      ASSERT_GE(s.x, 0.0);
      ASSERT_LT(s.x, 1.0);
      ASSERT_GE(s.y, 0.0);
      ASSERT_LT(s.y, 1.0);
      if (grid) {
        cells.insert(static_cast<int>(s.x * side) + side * static_cast<int>(s.y * side));
      } else {
        columns.insert(static_cast<int>(s.x * count));
        rows.insert(static_cast<int>(s.y * count));
      }
    }
    if (grid) {
      EXPECT_EQ(cells.size(), static_cast<std::size_t>(count)) << count;
    } else {
      EXPECT_EQ(columns.size(), static_cast<std::size_t>(count)) << count;
      EXPECT_EQ(rows.size(), static_cast<std::size_t>(count)) << count;
    }
  }
  EXPECT_EQ(stratifiedSample(0, 1, 99u), glm::dvec2(0.5, 0.5));
}

}  // namespace
}  // namespace confvis::embree
