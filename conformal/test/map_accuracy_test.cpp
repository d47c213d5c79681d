// Map error and kink measurement (map_accuracy.hpp) on maps whose answer is known.
#include "confvis/conformal/map_accuracy.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "display_test_configs.hpp"

namespace confvis {
namespace {

constexpr double kDegree = std::numbers::pi / 180;

DisplayMap mapAt(const DisplayConfig& config, double edge) {
  DisplayMapOptions options;
  options.edgeLength = edge;
  return computeDisplayMap(config, options);
}

// The exact identity on the display: the target mesh as its own source.
DisplayMap identityOn(const DisplayMap& map) {
  DisplayMap id;
  id.source = map.target;
  id.target = map.target;
  return id;
}

TEST(MapAccuracy, TheIdentityHasNoErrorAndNoKinks) {
  const DisplayConfig config = testing::shipped("cave5");
  const DisplayMap id = identityOn(mapAt(config, 0.6));
  const MapError error = measureMapError(config, id, id, 24);
  EXPECT_EQ(error.samples, 5u * 24 * 24);
  EXPECT_LT(error.max, 1e-6);
  const KinkStats kinks = measureKinks(config, id, 6);
  EXPECT_GT(kinks.samples, 20u);  // the lines do cross elements
  EXPECT_LT(kinks.max, 1e-4);
}

// The front half of a box seen from its centre covers exactly the front hemisphere, the source:
// the true map is the identity, so the error is the discretisation's alone. It must fall with
// the edge length (second order away from the corners, issue 22).
TEST(MapAccuracy, ErrorAgainstTheTrueMapFallsWithRefinement) {
  const DisplayConfig config = testing::frontHemisphereDisplay();
  std::vector<MapError> errors;
  for (double edge : {0.4, 0.2, 0.1}) {
    const DisplayMap map = mapAt(config, edge);
    errors.push_back(measureMapError(config, map, identityOn(map), 32));
  }
  for (std::size_t i = 1; i < errors.size(); ++i) {
    EXPECT_LT(errors[i].p50, 0.6 * errors[i - 1].p50) << i;
    EXPECT_LT(errors[i].p99, 0.8 * errors[i - 1].p99) << i;
  }
  EXPECT_GT(errors[0].p50, 1e-3);  // a real error is measured, not zero
}

// Two triangles sharing an edge; the target moves the second triangle's far corner, so T_geom is
// the identity on the first triangle and d -> normalize(M d) on the second, M = T S^-1 (columns:
// corners). A great circle crossing the shared edge at x turns by the angle between its tangent
// t and the image tangent (I - x x^T) M t there.
TEST(MapAccuracy, TheKinkOfATwoTriangleMapMatchesItsClosedForm) {
  const Vec3d a = normalized(Vec3d(-0.1, -0.1, -1)), b = normalized(Vec3d(0.1, 0.1, -1));
  const Vec3d c = normalized(Vec3d(0.1, -0.1, -1)), d = normalized(Vec3d(-0.1, 0.1, -1));
  const Vec3d moved = normalized(Vec3d(-0.13, 0.08, -1));
  DisplayMap map;
  // Counter-clockwise seen from the centre (looking along -z: x right, y up).
  map.source.sphere = {a, c, b, d};
  map.source.triangles = {{0, 1, 2}, {0, 2, 3}};
  map.source.disk = {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}};
  map.source.boundary = {0, 1, 2, 3};
  map.target = map.source;
  map.target.sphere[3] = moved;
  const DisplayMapEvaluator eval(map);
  // A line through the first triangle's middle, crossing the diagonal a-b.
  const Vec3d start = normalized(a + b + c);
  const Vec3d tangent = normalized(cross(start, Vec3d(0.3, 1, 0)));
  const std::vector<double> turns = kinkTurns(eval, {{start, tangent}}, 0.2, 1e-3, {}, 3);
  ASSERT_EQ(turns.size(), 1u);
  // Closed form: where the great circle meets the plane through the origin, a and b.
  const Vec3d planeNormal = normalized(cross(a, b)), lineNormal = normalized(cross(start, tangent));
  Vec3d x = normalized(cross(planeNormal, lineNormal));
  if (dot(x, start) < 0) x = -x;
  const Vec3d t = normalized(cross(lineNormal, x));  // the line's tangent at x
  const glm::dmat3 S(a, b, d), T(a, b, moved);
  const Vec3d image = T * glm::inverse(S) * t;
  const Vec3d projected = image - dot(image, x) * x;
  const double expected = angleBetween(t, projected) / kDegree;
  EXPECT_GT(expected, 1.0);
  EXPECT_NEAR(turns[0], expected, 1e-4);
}

// The four top corners (the target's, with the cut leaves there) and the images of the
// source's boundary corners (the copies of the cut's centres), all where the ceiling is missing:
// on the walls' top edges.
TEST(MapAccuracy, Cave5IsSingularAtItsTopCornersAndAlongItsTopEdges) {
  const std::vector<Vec3d> corners = singularCorners(mapAt(testing::shipped("cave5"), 0.6));
  int atCorners = 0;
  for (const Vec3d& d : corners) {
    const double major = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
    EXPECT_NEAR(d.y, major, 1e-3);  // on the top edge of a wall (y = 1.5 on the 3 m cube)
    const Vec3d onCube = d / major;
    atCorners += std::abs(std::abs(onCube.x) - 1) < 1e-9 && std::abs(std::abs(onCube.z) - 1) < 1e-9;
  }
  EXPECT_EQ(atCorners, 4);
  EXPECT_GE(corners.size(), 8u);
}

// Issue 22 point 2: a mesh graded toward the singular corners (the map is a power of the
// distance there) is far more accurate than uniform edges of the same base length, against a
// finer graded map; away from the corners nothing changes, so the median stays put.
TEST(MapAccuracy, GradingTowardTheSingularCornersCutsTheTailOfTheError) {
  const DisplayConfig config = testing::shipped("cave5");
  DisplayMapOptions options;
  options.grading.radiusDegrees = 20;
  options.edgeLength = 0.15;
  const DisplayMap reference = computeDisplayMap(config, options);
  options.edgeLength = 0.6;
  const DisplayMap graded = computeDisplayMap(config, options);
  options.grading.radiusDegrees = 0;
  const DisplayMap uniform = computeDisplayMap(config, options);
  EXPECT_GT(graded.target.sphere.size(), uniform.target.sphere.size());
  const MapError u = measureMapError(config, uniform, reference, 32);
  const MapError g = measureMapError(config, graded, reference, 32);
  EXPECT_LT(g.p99, 0.5 * u.p99) << u.p99 << " " << g.p99;
  EXPECT_LT(g.max, u.max);
  EXPECT_LT(g.p50, 1.5 * u.p50);
}

}  // namespace
}  // namespace confvis
