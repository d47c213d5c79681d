#pragma once
// A minimal double-precision 3-vector for direction maths in confvis_base, which stays free of
// Eigen and glm so every module (and users' applications) can link it without either.
#include <cmath>

namespace confvis {

struct Vec3d {
  double x = 0, y = 0, z = 0;

  friend bool operator==(const Vec3d&, const Vec3d&) = default;
  friend Vec3d operator+(const Vec3d& a, const Vec3d& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
  }
  friend Vec3d operator-(const Vec3d& a, const Vec3d& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
  }
  friend Vec3d operator-(const Vec3d& a) { return {-a.x, -a.y, -a.z}; }
  friend Vec3d operator*(double s, const Vec3d& a) { return {s * a.x, s * a.y, s * a.z}; }
  friend Vec3d operator*(const Vec3d& a, double s) { return s * a; }
};

inline double dot(const Vec3d& a, const Vec3d& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(const Vec3d& a) { return std::sqrt(dot(a, a)); }
// Unit vector along a; the caller guarantees a != 0.
inline Vec3d normalized(const Vec3d& a) { return (1.0 / norm(a)) * a; }
// Angle between two non-zero vectors in radians; atan2 stays accurate for tiny angles.
inline double angleBetween(const Vec3d& a, const Vec3d& b) {
  return std::atan2(norm(cross(a, b)), dot(a, b));
}
inline bool isFinite(const Vec3d& a) {
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

}  // namespace confvis
