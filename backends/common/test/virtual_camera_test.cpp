#include <gtest/gtest.h>

#include "confvis/backends/render_backend.hpp"

namespace confvis {
namespace {

void expectNear(const glm::dvec3& a, const glm::dvec3& b) {
  EXPECT_NEAR(a.x, b.x, 1e-12);
  EXPECT_NEAR(a.y, b.y, 1e-12);
  EXPECT_NEAR(a.z, b.z, 1e-12);
}

TEST(VirtualCamera, PositiveYawTurnsLeftAndPositivePitchLooksUp) {
  VirtualCamera camera;
  camera.yawDegrees = 90;
  // Forward (-z) turns to the left (-x); up stays up.
  expectNear(camera.rotation() * glm::dvec3(0, 0, -1), {-1, 0, 0});
  expectNear(camera.rotation() * glm::dvec3(0, 1, 0), {0, 1, 0});
  camera = {};
  camera.pitchDegrees = 90;
  expectNear(camera.rotation() * glm::dvec3(0, 0, -1), {0, 1, 0});
  camera.yawDegrees = 90;  // pitch about the turned x axis: still straight up
  expectNear(camera.rotation() * glm::dvec3(0, 0, -1), {0, 1, 0});
  camera.pitchDegrees = 0;
  EXPECT_NEAR(glm::determinant(camera.rotation()), 1.0, 1e-12);
}

}  // namespace
}  // namespace confvis
