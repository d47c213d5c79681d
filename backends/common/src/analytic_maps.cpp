#include "confvis/backends/analytic_maps.hpp"

#include <cmath>
#include <utility>

#include "confvis/base/error.hpp"

namespace confvis {

namespace {


bool inCeilingCone(const glm::dvec3& d) {
  return d.y >= std::abs(d.x) && d.y >= std::abs(d.z);
}

}  // namespace

RetargetMap rotationMap(const glm::dmat3& rotation, int resolution, const glm::dvec3& reference) {
  RetargetMap map;
  map.reference = reference;
  map.ray = CubeMap(resolution);
  map.geom = CubeMap(resolution);
  const glm::dmat3 inverse = glm::transpose(rotation);
  fillCubeMap(map.ray, [&](const Vec3d& d) { return std::pair{rotation * d, true}; });
  fillCubeMap(map.geom, [&](const Vec3d& v) { return std::pair{inverse * v, true}; });
  return map;
}

glm::dvec3 stereographicDilation(const glm::dvec3& d, double lambda) {
  // Stereographic coordinate from the zenith (0, 1, 0); the zenith itself is a fixed point.
  const double denominator = 1.0 - d.y;
  if (denominator <= 1e-15) return {0.0, 1.0, 0.0};
  const double a = lambda * d.x / denominator, b = lambda * d.z / denominator;
  const double r2 = a * a + b * b;
  return {2.0 * a / (1.0 + r2), (r2 - 1.0) / (r2 + 1.0), 2.0 * b / (1.0 + r2)};
}

RetargetMap ceilinglessDilationMap(double lambda, int resolution, const glm::dvec3& reference) {
  if (!(lambda > 0.0) || !std::isfinite(lambda))
    throw Error(ErrorCode::InvalidInput, "the dilation factor must be positive");
  RetargetMap map;
  map.reference = reference;
  map.ray = CubeMap(resolution);
  map.geom = CubeMap(resolution);
  fillCubeMap(map.ray, [&](const Vec3d& d) {
    return std::pair{stereographicDilation(d, lambda), !inCeilingCone(d)};
  });
  fillCubeMap(map.geom, [&](const Vec3d& v) {
    const glm::dvec3 physical = stereographicDilation(v, 1.0 / lambda);
    return std::pair{physical, !inCeilingCone(physical)};
  });
  return map;
}

}  // namespace confvis
