// Meshes graded toward a display's singular corners (issue 22): the spherical route maps them
// without stalling into its Euclidean fallback.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "confvis/base/error.hpp"
#include "confvis/conformal/disk_map.hpp"
#include "confvis/conformal/display_template.hpp"
#include "display_test_configs.hpp"

using namespace confvis;

namespace {

// cave3's source (the box with back, floor and ceiling missing, cut along their tree) at 20 cm,
// graded 20 degrees down to 1/64 of the edge, on the unit sphere around the reference.
std::vector<glm::dvec3> gradedCave3Source(std::vector<std::array<int, 3>>& triangles) {
  const DisplayConfig config = confvis::testing::shipped("cave3");
  const DisplayTemplates templates =
      buildDisplayTemplates(config, 0.2, {.radiusDegrees = 20, .minScale = 1.0 / 64});
  std::vector<glm::dvec3> sphere;
  for (const glm::dvec3& p : templates.source.points)
    sphere.push_back(glm::normalize(p - config.reference));
  triangles = templates.source.triangles;
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
