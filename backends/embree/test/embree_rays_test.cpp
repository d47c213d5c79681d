// The pieces under the Embree backend's camera rays: the curved-ray march against closed forms,
// the per-wall map grid against direct map lookups, and the stratified sample patterns.
#include <gtest/gtest.h>

#include <random>
#include <set>

#include "../src/camera_rays.hpp"
#include "../src/sampling.hpp"
#include "../src/wall_map_grid.hpp"
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

// The grid interpolates the map's lookups: in a wall's interior it reproduces them, and the
// exact map, to 1-2 % of a full-resolution pixel (~1e-3 rad at a CAVE wall's centre). Within half
// a map texel of a cube face edge the lookup itself is rougher (sampleBilinear fetches the
// neighbouring face's nearest texel: up to ~1e-3 rad off the exact map there) and the grid
// follows it to 0.2 pixel.
TEST(WallMapGrid, MatchesDirectMapLookupsFarBelowAPixel) {
  const DisplayConfig config = test::shippedConfig("cave5");
  const double lambda = 1.5;
  const RetargetMap map = ceilinglessDilationMap(lambda, 256);
  const ConformalWarp warp(map);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto angle = [](const glm::dvec3& a, const glm::dvec3& b) {
    return std::acos(std::min(1.0, glm::dot(glm::normalize(a), glm::normalize(b))));
  };
  for (const Wall& wall : config.walls) {
    SCOPED_TRACE(wall.name);
    const double spacing = WallMapGrid::spacingFor(wall, config.reference, 256, 1.0);
    EXPECT_GT(spacing, 1.0);  // coarser than the full-resolution pixels...
    EXPECT_LT(spacing, 4.0);  // ...but within half a texel (7.5 px)
    const WallMapGrid grid(warp, wall, spacing);
    double interiorWorst = 0, interiorAgainstTruth = 0, worst = 0;
    int litDisagreements = 0;
    for (int k = 0; k < 4000; ++k) {
      const double px = unit(rng) * wall.width, py = unit(rng) * wall.height;
      const glm::dvec3 p = wall.pointAt(px / wall.width, 1.0 - py / wall.height);
      const ConformalWarp::Lookup direct = warp.lookup(p - config.reference);
      const WallMapGrid::Sample s = grid.at(static_cast<float>(px), static_cast<float>(py));
      if ((s.alpha >= 0.5f) != direct.lit) ++litDisagreements;
      const glm::dvec3 got(s.direction);
      const bool interior = std::min({px, py, wall.width - px, wall.height - py}) > 8.0;
      if (interior) interiorWorst = std::max(interiorWorst, angle(got, direct.direction));
      const glm::dvec3 truth = stereographicDilation(glm::normalize(p - config.reference), lambda);
      if (interior) interiorAgainstTruth = std::max(interiorAgainstTruth, angle(got, truth));
      worst = std::max(worst, angle(got, direct.direction));
    }
    EXPECT_LT(interiorWorst, 1e-5);
    EXPECT_LT(interiorAgainstTruth, 2e-5);
    EXPECT_LT(worst, 2e-4);
    EXPECT_EQ(litDisagreements, 0);
  }
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
