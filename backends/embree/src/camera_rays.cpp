#include "camera_rays.hpp"

#include <cmath>
#include <limits>

#include "confvis/base/error.hpp"

namespace confvis::embree {

namespace {

// Eyes closer than this to c are the centre eye (metres).
constexpr double kCentreEyeTolerance = 1e-9;

}  // namespace

int curvedRay(const ConformalWarp& warp, const glm::dvec3& eye, const glm::dvec3& u,
              int segments, glm::dvec3* vertices, glm::dvec3& tail, double emptyRadius) {
  const glm::dvec3 c = warp.reference();
  const glm::dvec3 a = eye - c;
  const double along = glm::dot(a, u);
  const glm::dvec3 perpendicular = a - along * u;
  const double h = glm::length(perpendicular);
  tail = warp.direction(u);
  const double eyeAngle = std::atan2(h, along);  // angle between u and dir(e - c), in [0, pi]
  if (h <= 1e-12 * (1.0 + glm::length(a)) || eyeAngle <= kAsymptoteAngle) {
    vertices[0] = warp.warpPoint(eye);
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
  // Vertex i lies h / sin(angle_i) from c: the leading vertices with angle_i above asin(h / R)
  // lie inside the empty ball of radius R (the eye too, where |e - c| < R), and so do the
  // segments between them (the ball is convex). The curve starts at the last of them.
  int first = 0;
  if (glm::length(a) < emptyRadius) {
    const double insideAbove = std::asin(std::min(1.0, h / emptyRadius));
    while (first < segments && angle * ratio > insideAbove) {
      angle *= ratio;
      ++first;
    }
  }
  const auto curvePoint = [&](double at) {
    return warp.warpPoint(foot + (h * std::cos(at) / std::sin(at)) * u);
  };
  int count = 0;
  vertices[count++] = first == 0 ? warp.warpPoint(eye) : curvePoint(angle);
  for (int i = first + 1; i <= segments; ++i) {
    angle *= ratio;
    vertices[count++] = curvePoint(angle);
  }
  return count;
}

namespace {

// The rays of `view`, or of the override where there is one.
OverrideRays raysOf(const WallView& view, const ViewOverride* custom) {
  if (custom)  // scaled as WallView::rayDirection's, which reach the wall plane at t = 1
    return overrideRays(*custom, view.wall->width, view.wall->height, view.nearDistance);
  const glm::dvec3 base = view.rayDirection(0.0, 0.0);
  return {view.eye_position, base, view.rayDirection(1.0, 0.0) - base,
          view.rayDirection(0.0, 1.0) - base};
}

}  // namespace

CameraRays::CameraRays(const WallView& view, const VirtualCamera& camera,
                       const glm::dvec3& reference, const ViewOverride* custom)
    : CameraRays(view, raysOf(view, custom), camera, reference) {
  custom_ = custom != nullptr;
}

CameraRays::CameraRays(const WallView& view, const OverrideRays& rays,
                       const VirtualCamera& camera, const glm::dvec3& reference)
    : view_(view),
      directionBase_(rays.base),
      directionStepX_(rays.stepX),
      directionStepY_(rays.stepY),
      reference_(reference),
      cameraPosition_(camera.position),
      rotation_(camera.rotation()),
      placedEye_(place(view.eye_position)),
      placedCentre_(camera.position),
      rotationF_(rotation_),
      plain_{rotation_ * directionBase_, rotation_ * directionStepX_,
             rotation_ * directionStepY_} {
  // Rows of the view matrix's rotation: the wall's right, up and normal.
  const glm::dmat4& v = view.view;
  wallRight_ = {v[0][0], v[1][0], v[2][0]};
  wallUp_ = {v[0][1], v[1][1], v[2][1]};
  wallNormal_ = {v[0][2], v[1][2], v[2][2]};
  const glm::dvec3 fromEye = reference - view.eye_position;
  cRight_ = glm::dot(fromEye, wallRight_);
  cUp_ = glm::dot(fromEye, wallUp_);
  cNormal_ = glm::dot(fromEye, wallNormal_);
  if (view.wall) {
    pixelsPerMetreX_ = view.wall->width / (view.right - view.left);
    pixelsPerMetreY_ = view.wall->height / (view.top - view.bottom);
    packet_.width = static_cast<float>(view.wall->width);
    packet_.height = static_cast<float>(view.wall->height);
    const Wall lit = view.wall->litRectangle();  // the view's pixels span the lit rectangle
    packet_.corner = glm::vec3(lit.upperLeft - reference);
    packet_.across = glm::vec3((lit.lowerRight - lit.lowerLeft) / static_cast<double>(view.wall->width));
    packet_.down = glm::vec3((lit.lowerLeft - lit.upperLeft) / static_cast<double>(view.wall->height));
  }
  packet_.right = glm::vec3(wallRight_);
  packet_.up = glm::vec3(wallUp_);
  packet_.normal = glm::vec3(wallNormal_);
  packet_.cRight = static_cast<float>(cRight_);
  packet_.cUp = static_cast<float>(cUp_);
  packet_.cNormal = static_cast<float>(cNormal_);
  packet_.nearDistance = static_cast<float>(view.nearDistance);
  packet_.left = static_cast<float>(view.left);
  packet_.top = static_cast<float>(view.top);
  packet_.pixelsPerMetreX = static_cast<float>(pixelsPerMetreX_);
  packet_.pixelsPerMetreY = static_cast<float>(pixelsPerMetreY_);
  packet_.base = glm::vec3(directionBase_);
  packet_.stepX = glm::vec3(directionStepX_);
  packet_.stepY = glm::vec3(directionStepY_);
  packet_.eye = glm::vec3(view.eye_position - reference);
}

CameraRays::CameraRays(const WallView& view, const VirtualCamera& camera,
                       const ConformalWarp& warp, const WallMapGrid& grid, StereoRays stereoRays,
                       int curvedSegments, const ViewOverride* custom)
    : CameraRays(view, camera, warp.reference(), custom) {
  if (curvedSegments < 1 || curvedSegments > kMaxCurvedSegments)
    throw Error(ErrorCode::InvalidInput, "curved rays need 1 to " +
                                             std::to_string(kMaxCurvedSegments) +
                                             " segments, got " + std::to_string(curvedSegments));
  warp_ = &warp;
  grid_ = &grid;
  stereoRays_ = stereoRays;
  curvedSegments_ = curvedSegments;
  eyeAtReference_ = glm::length(view.eye_position - reference_) < kCentreEyeTolerance;
  if (!eyeAtReference_ && stereoRays == StereoRays::Fast) targetShift_ = packet_.eye;
}

void CameraRays::setTailGrid(const TailGrid* grid) {
  // Stereo eyes of a wall's own rays only: an override's pixel is not the wall's pixel.
  tailGrid_ = warp_ && !eyeAtReference_ && !custom_ && view_.wall ? grid : nullptr;
  if (!tailGrid_) return;
  // The ray from c parallel to p - e meets the wall's plane (n.(x - e) = -near) at
  // q = c + k (p - e), k = (near + cNormal) / near: in wall pixels q = k p + offset.
  const double near = view_.nearDistance, k = (near + cNormal_) / near;
  const double offsetX = (cRight_ + (k - 1.0) * view_.left) * pixelsPerMetreX_;
  const double offsetY = ((1.0 - k) * view_.top - cUp_) * pixelsPerMetreY_;
  // w = e - c = a right + b up + gamma x, x = q - c: gamma = w.n / x.n, the same for every q;
  // a = w.right - gamma x.right, b = w.up - gamma x.up, affine in q (tail_grid.hpp).
  const double gamma = cNormal_ / (near + cNormal_);
  AsymptoteFrame& f = asymptote_;
  f.scale = static_cast<float>(k);
  f.offsetX = static_cast<float>(offsetX);
  f.offsetY = static_cast<float>(offsetY);
  f.aBase = static_cast<float>(-cRight_ - gamma * (view_.left - cRight_) -
                               gamma * offsetX / pixelsPerMetreX_);
  f.aPerPx = static_cast<float>(-gamma * k / pixelsPerMetreX_);
  f.bBase = static_cast<float>(-cUp_ - gamma * (view_.top - cUp_) + gamma * offsetY / pixelsPerMetreY_);
  f.bPerPy = static_cast<float>(gamma * k / pixelsPerMetreY_);
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
  if (!eyeAtReference_)
    throw Error(ErrorCode::Internal, "straightDirection: stereo eyes use their packet rays");
  glm::dvec3 wallPoint;
  const WallMapGrid::Sample pixel = mapSample(px, py, wallPoint);
  if (!(pixel.alpha >= 0.5f)) return false;
  direction = centreDirection(pixel.direction);
  return true;
}

WallMapGrid::Sample CameraRays::mapSample(double px, double py, glm::dvec3& wallPoint) const {
  const glm::dvec3 toWall = directionBase_ + px * directionStepX_ + py * directionStepY_;
  if (!custom_) {  // WallView::rayDirection reaches the wall at t = 1 through its own pixel
    wallPoint = view_.eye_position + toWall;
    return grid_->at(static_cast<float>(px), static_cast<float>(py));
  }
  // Where the override's ray meets the wall's plane (mapDirections' plane), in wall pixels.
  const double towardWall = glm::dot(toWall, wallNormal_);
  const double t = towardWall < 0.0 ? -view_.nearDistance / towardWall : -1.0;
  wallPoint = view_.eye_position + (t > 0.0 ? t : 1.0) * toWall;
  if (t > 0.0) {
    const glm::dvec3 onWall = t * toWall;
    const Wall& wall = *view_.wall;
    const double wx = (glm::dot(onWall, wallRight_) - view_.left) * pixelsPerMetreX_;
    const double wy = (view_.top - glm::dot(onWall, wallUp_)) * pixelsPerMetreY_;
    if (wx >= 0.0 && wy >= 0.0 && wx <= wall.width && wy <= wall.height)
      return grid_->at(static_cast<float>(wx), static_cast<float>(wy));
  }
  const ConformalWarp::Lookup exact = warp_->lookup(glm::normalize(wallPoint - reference_));
  return {glm::vec3(exact.direction), exact.lit ? 1.0f : 0.0f};
}

double CameraRays::curvedReach() const {
  return glm::length(view_.eye_position - reference_) / std::sin(kAsymptoteAngle);
}

void CameraRays::curvedPath(double px, double py, RayPath& path) const {
  const glm::dvec3 toWall = directionBase_ + px * directionStepX_ + py * directionStepY_;
  std::array<glm::dvec3, kMaxCurvedSegments + 2> vertices;
  glm::dvec3 tailDirection;
  path.lit = true;
  path.vertexCount = curvedRay(*warp_, view_.eye_position, glm::normalize(toWall), curvedSegments_,
                               vertices.data(), tailDirection, emptyRadius_);
  for (int i = 0; i < path.vertexCount; ++i) path.vertices[i] = place(vertices[i]);
  path.tail = turn(tailDirection);
}

}  // namespace confvis::embree
