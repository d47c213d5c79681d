#pragma once
// Analytic retarget maps with closed-form inverses, standing in for baked maps in the renderer
// tests (conformality does not matter to a renderer, only that geom and ray are inverse).
#include <cmath>
#include <optional>
#include <utility>

#include <glm/glm.hpp>

#include "confvis/conformal/retarget_map.hpp"

namespace confvis::test {


// Rotation by `degrees` about +y (positive turns +x towards -z): T_geom(v) = R v.
inline glm::dvec3 rotateAboutY(const glm::dvec3& v, double degrees) {
  const double a = glm::radians(degrees), c = std::cos(a), s = std::sin(a);
  return {c * v.x + s * v.z, v.y, -s * v.x + c * v.z};
}

inline RetargetMap rotationMap(int resolution, double degrees) {
  RetargetMap map = RetargetMap::identity(resolution);
  fillCubeMap(map.geom, [&](const Vec3d& v) {
    return std::pair{rotateAboutY(v, degrees), true};
  });
  fillCubeMap(map.ray, [&](const Vec3d& d) {
    return std::pair{rotateAboutY(d, -degrees), true};
  });
  return map;
}

// Azimuth about +y measured from -z towards +x, in (-pi, pi]; elevation kept.
inline glm::dvec3 scaleAzimuth(const glm::dvec3& v, double factor) {
  const double azimuth = std::atan2(v.x, -v.z);
  const double horizontal = std::hypot(v.x, v.z);
  return {horizontal * std::sin(factor * azimuth), v.y, -horizontal * std::cos(factor * azimuth)};
}

// The whole sphere squeezed onto the front half-space z < 0 by halving the azimuth: T_geom is
// continuous except across the cut, the back half-meridian {x = 0, z > 0}, whose two sides land
// on opposite edges (x = +-1, z = 0) of the image. T_ray doubles the azimuth of front directions.
inline RetargetMap azimuthSqueezeMap(int resolution) {
  RetargetMap map = RetargetMap::identity(resolution);
  fillCubeMap(map.geom, [](const Vec3d& v) { return std::pair{scaleAzimuth(v, 0.5), true}; });
  fillCubeMap(map.ray, [](const Vec3d& d) {
    return std::pair{scaleAzimuth(d, 2.0), d.z < 0.0};
  });
  return map;
}

// T_ray of azimuthSqueezeMap in closed form: nullopt behind the viewer (nothing drawn there).
inline std::optional<glm::dvec3> squeezeToVirtual(const glm::dvec3& d) {
  if (d.z >= 0.0) return std::nullopt;
  return scaleAzimuth(d, 2.0);
}

// A conformal map of the whole sphere onto itself, smooth everywhere (no cut): in the
// stereographic coordinate w = (x, y) / (1 - z) seen from the back pole +z, T_geom scales w by
// 1 / zoom, pulling every direction towards the front pole -z (a Moebius dilation). Straight
// edges bend into circular arcs, as under a baked conformal map away from its cut.
inline glm::dvec3 scaleStereographic(const glm::dvec3& v, double factor) {
  if (v.z >= 1.0) return v;  // the back pole stays put
  const glm::dvec2 w = factor * glm::dvec2(v.x, v.y) / (1.0 - v.z);
  const double w2 = glm::dot(w, w);
  return glm::dvec3(2.0 * w.x, 2.0 * w.y, w2 - 1.0) / (w2 + 1.0);
}

inline RetargetMap zoomMap(int resolution, double zoom) {
  RetargetMap map = RetargetMap::identity(resolution);
  fillCubeMap(map.geom, [&](const Vec3d& v) {
    return std::pair{scaleStereographic(v, 1.0 / zoom), true};
  });
  fillCubeMap(map.ray, [&](const Vec3d& d) {
    return std::pair{scaleStereographic(d, zoom), true};
  });
  return map;
}

}  // namespace confvis::test
