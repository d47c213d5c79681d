#pragma once
// The tracked viewer: a head pose and the eye positions derived from it.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {

enum class Eye { Left, Center, Right };

// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
struct HeadPose {
  glm::dvec3 position{0.0};
  // Identity: looking down -z with +y up, the physical frame's "forward" (design note §2).
  // Write HeadPose{position} for the identity; HeadPose{position, {}} is the zero quaternion.
  glm::dquat orientation{1.0, 0.0, 0.0, 0.0};
};

// Eyes sit at +-eyeSeparation/2 along the head's right axis (+x rotated by the orientation);
// Left is the minus side, Center is the head position itself.
glm::dvec3 eyePosition(const HeadPose& head, Eye eye, double eyeSeparation);

}  // namespace confvis
