#include "confvis/engine/viewer.hpp"

namespace confvis {

glm::dvec3 eyePosition(const HeadPose& head, Eye eye, double eyeSeparation) {
  const double side = eye == Eye::Left ? -0.5 : eye == Eye::Right ? 0.5 : 0.0;
  const glm::dvec3 headRight = head.orientation * glm::dvec3(1.0, 0.0, 0.0);
  return head.position + side * eyeSeparation * headRight;
}

}  // namespace confvis
