// Meshes graded toward a display's singular corners (issue 22): the spherical route maps them
// without stalling into its Euclidean fallback.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "confvis/base/error.hpp"
#include "confvis/conformal/bake.hpp"
#include "confvis/conformal/disk_map.hpp"
#include "confvis/conformal/display_map.hpp"
#include "confvis/conformal/display_template.hpp"
#include "confvis/conformal/map_alignment_quality.hpp"
#include "display_test_configs.hpp"

using namespace confvis;

namespace {

// cave3's source (the box with back, floor and ceiling missing, cut along their tree) at 20 cm,
// graded 20 degrees down to 1/64 of the edge, on the unit sphere around the reference.
std::vector<glm::dvec3> gradedCave3Source(std::vector<std::array<int, 3>>& triangles,
                                          bool target = false) {
  const DisplayConfig config = confvis::testing::shipped("cave3");
  const DisplayTemplates templates =
      buildDisplayTemplates(config, 0.2, {.radiusDegrees = 20, .minScale = 1.0 / 64});
  const TemplateMesh& mesh = target ? templates.target : templates.source;
  std::vector<glm::dvec3> sphere;
  for (const glm::dvec3& p : mesh.points) sphere.push_back(glm::normalize(p - config.reference));
  triangles = mesh.triangles;
  return sphere;
}

}  // namespace

// Started from the embedded metric, the flow to a hemisphere crawls (max error ~0.14 rising to
// 0.28 in 20 Newton steps: the rings of tiny triangles around each cut leaf must all open from
// 2π to π); started from the corners' z^(π/α) factor it converges directly. Without any stalled
// stage allowed, only the guessed start reaches the tolerance.
TEST(GradedDisplayMap, CornerGuessLetsTheSphericalRouteMapCave3sGradedSource) {
  std::vector<std::array<int, 3>> triangles;
  const std::vector<glm::dvec3> points = gradedCave3Source(triangles);
  ASSERT_GT(points.size(), 5000u);  // graded: ~6.2k against ~3.2k uniform
  conformal::DiskMapOptions options;
  options.geometry = conformal::Geometry::Spherical;
  options.scheme = conformal::Scheme::InversiveDistance;  // as the display map
  options.maxIterations = 30;
  options.maxStalledStages = 0;
  options.cornerGuess = true;
  const conformal::DiskMap guessed = conformal::computeDiskMap(points, triangles, options);
  EXPECT_EQ(guessed.geometry, conformal::Geometry::Spherical);
  EXPECT_LE(guessed.flow.maxCurvatureError, 1e-10);
  EXPECT_LE(guessed.flow.iterations, 12);
  options.cornerGuess = false;
  EXPECT_THROW(conformal::computeDiskMap(points, triangles, options), Error);
}

// cave3's graded target (front, left and right walls): continuation from the corner guess
// follows a branch that folds before the hemisphere (its Newton step at s = 1 is ~4 in u, front
// down and the walls' back edges up by e^4), so every stage from s ~0.77 on crawls. Started from
// the Euclidean route's hemisphere, the spherical flow converges directly.
TEST(GradedDisplayMap, EuclideanHemisphereStartLetsTheSphericalRouteMapCave3sGradedTarget) {
  std::vector<std::array<int, 3>> triangles;
  const std::vector<glm::dvec3> points = gradedCave3Source(triangles, true);
  ASSERT_GT(points.size(), 3000u);  // graded: ~3.7k against ~1.6k uniform
  conformal::DiskMapOptions options;
  options.geometry = conformal::Geometry::Spherical;
  options.scheme = conformal::Scheme::InversiveDistance;
  options.maxIterations = 30;
  options.maxStalledStages = 3;
  options.cornerGuess = true;
  EXPECT_THROW(conformal::computeDiskMap(points, triangles, options), Error);
  conformal::DiskMapOptions euclidean = options;
  euclidean.geometry = conformal::Geometry::Euclidean;
  options.hemisphereGuess = conformal::computeDiskMap(points, triangles, euclidean).uv;
  options.maxStalledStages = 0;
  const conformal::DiskMap guessed = conformal::computeDiskMap(points, triangles, options);
  EXPECT_EQ(guessed.geometry, conformal::Geometry::Spherical);
  EXPECT_LE(guessed.flow.maxCurvatureError, 1e-10);
  EXPECT_LE(guessed.flow.iterations, 8);
  options.hemisphereGuess.pop_back();
  EXPECT_THROW(conformal::computeDiskMap(points, triangles, options), Error);
}

// The display map takes that route: cave3 graded maps spherical on both sides, so its map keeps
// the display's left/right and top/bottom mirror symmetry (the Euclidean route's removed face
// broke it).
TEST(GradedDisplayMap, Cave3GradedMapsSphericallyAndStaysMirrorSymmetric) {
  const DisplayConfig config = confvis::testing::shipped("cave3");
  DisplayMapOptions options;
  options.edgeLength = 0.2;
  options.grading = {.radiusDegrees = 20, .minScale = 1.0 / 64};
  const DisplayMap map = computeDisplayMap(config, options);
  EXPECT_EQ(map.stats["source"]["route"], "spherical");
  EXPECT_EQ(map.stats["target"]["route"], "spherical");
  BakeOptions bake;
  bake.reference = {config.reference.x, config.reference.y, config.reference.z};
  const RetargetMap baked = bakeRetargetMap(map, 48, bake);
  for (const Vec3d& normal : {Vec3d{1, 0, 0}, Vec3d{0, 1, 0}}) {
    const MirrorAsymmetry a = measureMirrorAsymmetry(baked, config, normal, 12);
    EXPECT_GT(a.samples, 100u);
    EXPECT_LE(a.max, 0.1) << "mirror normal (" << normal.x << ", " << normal.y << ", "
                          << normal.z << "), worst on " << a.worstWall;
  }
}
