#include "confvis/engine/view.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <string>

#include "confvis/base/error.hpp"
#include "display_checks.hpp"

namespace confvis {
namespace {

void checkDepthRange(double near, double far) {
  if (!(near > 0.0) || !(far > near))
    throw Error(ErrorCode::InvalidInput, "projection needs 0 < near < far, got near " +
                                             std::to_string(near) + ", far " + std::to_string(far));
}

}  // namespace

glm::dmat4 WallView::projectionGL(double near, double far) const {
  checkDepthRange(near, far);
  const double scale = near / nearDistance;  // wall-plane extents -> near-plane extents
  return glm::frustumRH_NO(left * scale, right * scale, bottom * scale, top * scale, near, far);
}

glm::dmat4 WallView::projectionVulkan(double near, double far) const {
  checkDepthRange(near, far);
  const double scale = near / nearDistance;
  glm::dmat4 flipY(1.0);
  flipY[1][1] = -1.0;  // Vulkan clip space has y pointing down
  return flipY *
         glm::frustumRH_ZO(left * scale, right * scale, bottom * scale, top * scale, near, far);
}

glm::dmat4 WallView::projectionVulkanReverseZ(double near) const {
  checkDepthRange(near, 2.0 * near);
  glm::dmat4 p(0.0);  // column-major: p[column][row]
  p[0][0] = 2.0 * nearDistance / (right - left);
  p[2][0] = (right + left) / (right - left);
  p[1][1] = -2.0 * nearDistance / (top - bottom);  // Vulkan clip space has y pointing down
  p[2][1] = -(top + bottom) / (top - bottom);
  p[3][2] = near;  // clip z = near, clip w = -z: depth near / -z
  p[2][3] = -1.0;
  return p;
}

glm::dvec3 WallView::rayDirection(double px, double py) const {
  const double x = left + px / wall->width * (right - left);
  const double y = top - py / wall->height * (top - bottom);
  // Rows of the view matrix's rotation are the wall's right, up and normal in world space.
  const glm::dvec3 wallRight(view[0][0], view[1][0], view[2][0]);
  const glm::dvec3 wallUp(view[0][1], view[1][1], view[2][1]);
  const glm::dvec3 wallNormal(view[0][2], view[1][2], view[2][2]);
  return x * wallRight + y * wallUp - nearDistance * wallNormal;
}

WallView makeWallView(const Wall& wall, const glm::dvec3& eyePos) {
  const Wall lit = wall.litRectangle();
  const glm::dvec3 vr = lit.right(), vu = lit.up(), vn = lit.normal();
  const glm::dvec3 va = lit.lowerLeft - eyePos, vb = lit.lowerRight - eyePos,
                   vc = lit.upperLeft - eyePos;
  WallView v;
  v.wall = &wall;
  v.eye_position = eyePos;
  v.nearDistance = -glm::dot(vn, va);
  if (v.nearDistance < detail::kLengthTolerance)
    throw Error(ErrorCode::InvalidInput,
                "wall '" + wall.name + "': the eye is on or behind the wall plane (distance " +
                    std::to_string(v.nearDistance) + " m), it cannot see the wall");
  v.left = glm::dot(vr, va);
  v.right = glm::dot(vr, vb);
  v.bottom = glm::dot(vu, va);
  v.top = glm::dot(vu, vc);
  // Kooima's M^T * T(-eye): rows of the rotation are right, up, normal.
  glm::dmat4 rotation(1.0);
  for (int i = 0; i < 3; ++i) {
    rotation[i][0] = vr[i];
    rotation[i][1] = vu[i];
    rotation[i][2] = vn[i];
  }
  v.view = rotation * glm::translate(glm::dmat4(1.0), -eyePos);
  return v;
}

std::vector<WallView> makeViews(const DisplayConfig& config, const HeadPose& head, Eye eye) {
  const glm::dvec3 eyePos = eyePosition(head, eye, config.eyeSeparation);
  std::vector<WallView> views;
  views.reserve(config.walls.size());
  for (const Wall& w : config.walls) {
    views.push_back(makeWallView(w, eyePos));
    views.back().eye = eye;
  }
  return views;
}

}  // namespace confvis
