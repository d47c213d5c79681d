#include <cmath>

#include <glm/gtc/constants.hpp>

#include "confvis/backends/render_backend.hpp"

namespace confvis {

glm::dmat3 VirtualCamera::rotation() const {
  const double yaw = glm::radians(yawDegrees), pitch = glm::radians(pitchDegrees);
  // Columns are the images of the physical x, y, z axes: R = R_y(yaw) * R_x(pitch).
  const glm::dmat3 ry{std::cos(yaw), 0, -std::sin(yaw), 0, 1, 0, std::sin(yaw), 0, std::cos(yaw)};
  const glm::dmat3 rx{1, 0, 0, 0, std::cos(pitch), std::sin(pitch), 0, -std::sin(pitch),
                      std::cos(pitch)};
  return ry * rx;
}

}  // namespace confvis
