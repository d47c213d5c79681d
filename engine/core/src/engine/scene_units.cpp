#include "confvis/engine/scene_units.hpp"

#include <cmath>
#include <cstdio>

#include "confvis/base/error.hpp"

namespace confvis {

double displayExtent(const DisplayConfig& display) {
  Bounds box;
  for (const Wall& wall : display.walls)
    for (const glm::dvec3& corner : wall.corners())
      box.extend(glm::vec3(corner));
  return box.empty() ? 0.0 : static_cast<double>(glm::length(box.max - box.min));
}

std::optional<std::string> sceneUnitsHint(const Scene& scene, const DisplayConfig& display) {
  const Bounds box = scene.bounds();
  if (box.empty()) return std::nullopt;
  const double sceneSize = glm::length(glm::dvec3(box.max) - glm::dvec3(box.min));
  const double displaySize = displayExtent(display);
  if (!(displaySize > 0.0) || !(sceneSize > kSceneUnitsHintRatio * displaySize)) return std::nullopt;
  char text[320];
  std::snprintf(text, sizeof text,
                "scene '%s' is %.0f m across, %.0f times the display '%s' (%.1f m); if the model "
                "is in millimetres, add --scene-scale 0.001 (centimetres: 0.01)",
                scene.name.c_str(), sceneSize, sceneSize / displaySize, display.name.c_str(),
                displaySize);
  return std::string(text);
}

void scaleScene(Scene& scene, double factor) {
  if (!(factor > 0.0) || !std::isfinite(factor))
    throw Error(ErrorCode::InvalidInput,
                "scene scale must be a positive number, got " + std::to_string(factor));
  for (Mesh& mesh : scene.meshes)
    for (glm::vec3& p : mesh.positions) p = glm::vec3(glm::dvec3(p) * factor);
  validateScene(scene);  // a huge factor overflows float: refused, naming the scene
}

}  // namespace confvis
