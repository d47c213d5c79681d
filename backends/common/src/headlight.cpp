#include "confvis/backends/headlight.hpp"

#include "confvis/conformal/retarget_map.hpp"

namespace confvis {

glm::dvec3 headlightPosition(const glm::dvec3& eye, const DisplayConfig& config,
                             const RetargetMap* map, const VirtualCamera& camera) {
  glm::dvec3 physical = eye;
  if (map != nullptr) {
    const glm::dvec3 c = map->reference;
    const double distance = glm::length(eye - c);
    if (distance > 1e-12) {
      const glm::dvec3 d = (eye - c) / distance;
      if (const auto v = map->toVirtual({d.x, d.y, d.z})) physical = c + distance * *v;
    }
  }
  return camera.position + camera.rotation() * (physical - config.reference);
}

}  // namespace confvis
