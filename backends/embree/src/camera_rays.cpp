#include "camera_rays.hpp"

#include <cmath>

#include "confvis/base/error.hpp"

namespace confvis::embree {

namespace {

// The angle (seen from c) at which the curved ray hands over to its straight asymptote. The
// curve's distance from its asymptote there is about h * angle * |F''| / 2, with h = |e - c|
// perpendicular to the ray (at most half the eye separation): ~0.02 mm for a 64 mm baseline.
constexpr double kAsymptoteAngle = 1e-3;
// Eyes closer than this to c are the centre eye (metres).
constexpr double kCentreEyeTolerance = 1e-9;

}  // namespace

int curvedRay(const ConformalWarp& warp, const glm::dvec3& eye, const glm::dvec3& u,
              int segments, glm::dvec3* vertices, glm::dvec3& tail) {
  const glm::dvec3 c = warp.reference();
  const glm::dvec3 a = eye - c;
  const double along = glm::dot(a, u);
  const glm::dvec3 perpendicular = a - along * u;
  const double h = glm::length(perpendicular);
  tail = warp.direction(u);
  vertices[0] = warp.warpPoint(eye);
  const double eyeAngle = std::atan2(h, along);  // angle between u and dir(e - c), in [0, pi]
  if (h <= 1e-12 * (1.0 + glm::length(a)) || eyeAngle <= kAsymptoteAngle) {
    // The ray lies on a line through c: W maps each half-line from c to a straight half-line.
    if (along >= 0.0) return 1;
    vertices[1] = c;
    return 2;
  }
  // Points q(s) = foot + s u with the angle atan2(h, s) at c stepping geometrically from
  // eyeAngle down to kAsymptoteAngle.
  const glm::dvec3 foot = c + perpendicular;
  const double ratio = std::pow(kAsymptoteAngle / eyeAngle, 1.0 / segments);
  double angle = eyeAngle;
  for (int i = 1; i <= segments; ++i) {
    angle *= ratio;
    const double s = h * std::cos(angle) / std::sin(angle);
    vertices[i] = warp.warpPoint(foot + s * u);
  }
  return segments + 1;
}

CameraRays::CameraRays(const WallView& view, const VirtualCamera& camera,
                       const glm::dvec3& reference)
    : view_(view),
      directionBase_(view.rayDirection(0.0, 0.0)),
      directionStepX_(view.rayDirection(1.0, 0.0) - directionBase_),
      directionStepY_(view.rayDirection(0.0, 1.0) - directionBase_),
      reference_(reference),
      cameraPosition_(camera.position),
      rotation_(camera.rotation()),
      placedEye_(place(view.eye_position)),
      rotationF_(rotation_),
      plain_{rotation_ * directionBase_, rotation_ * directionStepX_,
             rotation_ * directionStepY_} {}

CameraRays::CameraRays(const WallView& view, const VirtualCamera& camera,
                       const ConformalWarp& warp, const WallMapGrid& grid, StereoRays stereoRays,
                       int curvedSegments)
    : CameraRays(view, camera, warp.reference()) {
  if (curvedSegments < 1 || curvedSegments > kMaxCurvedSegments)
    throw Error(ErrorCode::InvalidInput, "curved rays need 1 to " +
                                             std::to_string(kMaxCurvedSegments) +
                                             " segments, got " + std::to_string(curvedSegments));
  warp_ = &warp;
  grid_ = &grid;
  stereoRays_ = stereoRays;
  curvedSegments_ = curvedSegments;
  eyeAtReference_ = glm::length(view.eye_position - reference_) < kCentreEyeTolerance;
}

glm::vec3 CameraRays::place(const glm::dvec3& p) const {
  return glm::vec3(cameraPosition_ + rotation_ * (p - reference_));
}

glm::vec3 CameraRays::turn(const glm::dvec3& d) const { return glm::vec3(rotation_ * d); }

bool CameraRays::straightDirection(double px, double py, glm::vec3& direction) const {
  const auto fx = static_cast<float>(px), fy = static_cast<float>(py);
  if (!warp_) {
    direction = plain_.at(fx, fy);
    return true;
  }
  const WallMapGrid::Sample pixel = grid_->at(fx, fy);
  if (!(pixel.alpha >= 0.5f)) return false;
  if (eyeAtReference_) {
    direction = centreDirection(pixel.direction);
    return true;
  }
  // Fast stereo: from the eye towards W(p), p = eye + toWall on the wall (WallView::rayDirection
  // is affine in px, py).
  const glm::dvec3 eye = view_.eye_position;
  const glm::dvec3 wallPoint = eye + directionBase_ + px * directionStepX_ + py * directionStepY_;
  const glm::dvec3 target = reference_ + glm::length(wallPoint - reference_) *
                                             glm::normalize(glm::dvec3(pixel.direction));  // W(p)
  direction = turn(glm::normalize(target - eye));
  return true;
}

void CameraRays::make(double px, double py, RayPath& path) const {
  path.vertexCount = 1;
  path.vertices[0] = placedEye_;
  if (straight()) {
    path.lit = straightDirection(px, py, path.tail);
    return;
  }
  const WallMapGrid::Sample pixel = grid_->at(static_cast<float>(px), static_cast<float>(py));
  path.lit = pixel.alpha >= 0.5f;
  if (!path.lit) return;
  const glm::dvec3 eye = view_.eye_position;
  // eye + toWall lies on the wall (WallView::rayDirection, which is affine in px, py)
  const glm::dvec3 toWall = directionBase_ + px * directionStepX_ + py * directionStepY_;
  std::array<glm::dvec3, kMaxCurvedSegments + 2> vertices;
  glm::dvec3 tail;
  path.vertexCount =
      curvedRay(*warp_, eye, glm::normalize(toWall), curvedSegments_, vertices.data(), tail);
  for (int i = 0; i < path.vertexCount; ++i) path.vertices[i] = place(vertices[i]);
  path.tail = turn(tail);
}

}  // namespace confvis::embree
