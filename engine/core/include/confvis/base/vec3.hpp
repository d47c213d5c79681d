#pragma once
// Directions and points are glm::dvec3 everywhere in confvis, the public API included (GLM, a
// header-only Debian package). Vec3d is the same type under the name older code uses, and the
// helpers below are the direction maths that code shares.
#include <cmath>

#include <glm/glm.hpp>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {

using Vec3d = glm::dvec3;

inline double dot(const glm::dvec3& a, const glm::dvec3& b) { return glm::dot(a, b); }
inline glm::dvec3 cross(const glm::dvec3& a, const glm::dvec3& b) { return glm::cross(a, b); }
inline double norm(const glm::dvec3& a) { return std::sqrt(dot(a, a)); }
// Unit vector along a; the caller guarantees a != 0.
inline glm::dvec3 normalized(const glm::dvec3& a) { return (1.0 / norm(a)) * a; }
// Angle between two non-zero vectors in radians; atan2 stays accurate for tiny angles.
inline double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(norm(cross(a, b)), dot(a, b));
}
inline bool isFinite(const glm::dvec3& a) {
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

}  // namespace confvis
