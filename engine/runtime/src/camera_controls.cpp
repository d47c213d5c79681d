#include "confvis/runtime/camera_controls.hpp"

#include <algorithm>
#include <cmath>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace confvis {

void CameraControls::update(const std::vector<std::unique_ptr<DisplayWindow>>& windows,
                            VirtualCamera& camera, double seconds) {
  glm::dvec3 move(0.0);  // x right, y up, z backwards, in the camera's yaw frame
  const DisplayWindow* dragging = nullptr;
  for (const auto& window : windows) {
    if (window->keyDown(GLFW_KEY_W)) move.z -= 1.0;
    if (window->keyDown(GLFW_KEY_S)) move.z += 1.0;
    if (window->keyDown(GLFW_KEY_A)) move.x -= 1.0;
    if (window->keyDown(GLFW_KEY_D)) move.x += 1.0;
    if (window->keyDown(GLFW_KEY_E)) move.y += 1.0;
    if (window->keyDown(GLFW_KEY_Q)) move.y -= 1.0;
    if (!dragging && window->dragging()) dragging = window.get();
  }
  if (glm::length(move) > 0.0) {
    const double yaw = glm::radians(camera.yawDegrees);  // positive turns left, about +y
    const glm::dvec3 right(std::cos(yaw), 0.0, -std::sin(yaw));
    const glm::dvec3 backwards(std::sin(yaw), 0.0, std::cos(yaw));
    camera.position += metresPerSecond * seconds *
                       glm::normalize(move.x * right + move.y * glm::dvec3(0, 1, 0) +
                                      move.z * backwards);
  }
  if (dragging) {
    double x = 0.0, y = 0.0;
    dragging->cursor(x, y);
    if (dragging == dragged_) {  // dragging right turns right, dragging down looks down
      camera.yawDegrees -= (x - lastX_) * degreesPerPixel;
      camera.pitchDegrees = std::clamp(camera.pitchDegrees - (y - lastY_) * degreesPerPixel,
                                       -89.0, 89.0);
    }
    lastX_ = x;
    lastY_ = y;
  }
  dragged_ = dragging;
}

}  // namespace confvis
