#pragma once
// Off-axis views of the walls: the generalized perspective projection of Kooima
// ("Generalized Perspective Projection", 2008). The frustum spans each wall's lit rectangle
// (the wall minus its bezels), the area its pixels cover.
#include <vector>

#include <glm/glm.hpp>

#include "confvis/base/export.hpp"
#include "confvis/engine/display_config.hpp"
#include "confvis/engine/viewer.hpp"

namespace confvis CONFVIS_API {

// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
// It points to its wall: the DisplayConfig must outlive it and stay unchanged.
struct WallView {
  const Wall* wall = nullptr;  // the configured wall; owned by the caller (e.g. DisplayConfig)
  Eye eye = Eye::Center;
  glm::dvec3 eye_position{0.0};
  // Frustum extents measured in the wall plane, in metres along the wall's right() and up()
  // axes from the foot of the perpendicular dropped from the eye onto that plane (Kooima's
  // l, r, b, t before scaling by near/d). nearDistance is d, the eye-to-plane distance; the
  // extents on a near plane at distance n are these times n / nearDistance.
  double left = 0, right = 0, bottom = 0, top = 0, nearDistance = 1;
  // World -> wall-aligned eye space: eye at the origin, x = wall right, y = wall up, the wall
  // at z = -nearDistance.
  glm::dmat4 view{1.0};

  // OpenGL clip space: x,y,z in [-1,1], y up.
  glm::dmat4 projectionGL(double near, double far) const;
  // Vulkan clip space: depth in [0,1], y down (the wall's upper edge at clip y = -1).
  glm::dmat4 projectionVulkan(double near, double far) const;
  // Vulkan clip space with reverse-Z and no far plane: depth near / distance along the wall's
  // normal, 1 on the near plane and falling towards 0 at infinity (clear depth 0, compare
  // GREATER). Float depth then keeps ~7 significant digits of the distance at any scale.
  glm::dmat4 projectionVulkanReverseZ(double near) const;
  // World-space direction (unnormalised, reaching the wall plane at t = 1) from the eye through
  // pixel-space point (px, py) of the lit area: px in [0, width], py in [0, height], py = 0 at
  // the top edge. Pixel (x, y) has its centre at (x + 0.5, y + 0.5).
  glm::dvec3 rayDirection(double px, double py) const;
};

// Throws Error(InvalidInput) naming the wall when the eye is on or behind the wall plane.
WallView makeWallView(const Wall& wall, const glm::dvec3& eyePos);

// One view per wall of `config`, in its order; the views point into config.walls.
std::vector<WallView> makeViews(const DisplayConfig& config, const HeadPose& head, Eye eye);

}  // namespace confvis
