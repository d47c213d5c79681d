#pragma once
// Ray casting against a Scene by brute force: the tests' stand-in for the renderers, so mesh
// colours can be compared with the closed-form scene colours.
#include <glm/glm.hpp>

#include <cmath>
#include <optional>

#include "confvis/engine/scene.hpp"

namespace confvis::test {

struct SceneHit {
  std::size_t mesh = 0;
  std::size_t triangle = 0;
  glm::vec2 barycentrics{0.0f};  // Embree's (u, v)
  double distance = 0.0;
  glm::dvec3 point{0.0};
};

// Möller-Trumbore in double precision; both triangle sides count.
inline std::optional<SceneHit> castRay(const Scene& scene, glm::dvec3 origin, glm::dvec3 direction) {
  std::optional<SceneHit> best;
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const glm::uvec3 tri = mesh.triangles[t];
      const glm::dvec3 p0(mesh.positions[tri.x]), p1(mesh.positions[tri.y]), p2(mesh.positions[tri.z]);
      const glm::dvec3 e1 = p1 - p0, e2 = p2 - p0;
      const glm::dvec3 pv = glm::cross(direction, e2);
      const double det = glm::dot(e1, pv);
      if (std::abs(det) < 1e-15) continue;
      const glm::dvec3 tv = origin - p0;
      const double u = glm::dot(tv, pv) / det;
      if (u < 0.0 || u > 1.0) continue;
      const glm::dvec3 qv = glm::cross(tv, e1);
      const double v = glm::dot(direction, qv) / det;
      if (v < 0.0 || u + v > 1.0) continue;
      const double distance = glm::dot(e2, qv) / det;
      if (distance <= 0.0 || (best && distance >= best->distance)) continue;
      best = SceneHit{m, t, glm::vec2(u, v), distance, origin + distance * direction};
    }
  }
  return best;
}

}  // namespace confvis::test
