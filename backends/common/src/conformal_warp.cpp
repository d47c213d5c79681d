#include "confvis/backends/conformal_warp.hpp"

#include <cmath>

#include "confvis/base/error.hpp"

namespace confvis {

ConformalWarp::ConformalWarp(const RetargetMap& map)
    : map_(&map), reference_(map.reference.x, map.reference.y, map.reference.z) {
  if (!isFinite(map.reference))
    throw Error(ErrorCode::InvalidInput, "retarget map: the reference point is not finite");
  const int n = map.ray.faceSize;
  if (n <= 0)
    throw Error(ErrorCode::InvalidInput, "retarget map: the ray cube map is empty");
  for (const ImageRGBA& face : map.ray.faces)
    if (face.width != n || face.height != n || face.pixels.size() != face.pixelCount() * 4)
      throw Error(ErrorCode::InvalidInput,
                  "retarget map: the ray cube map's faces are not all " + std::to_string(n) +
                      "x" + std::to_string(n));
}

ConformalWarp::Lookup ConformalWarp::lookup(const glm::dvec3& physicalDir) const {
  const std::array<float, 4> s =
      sampleBilinear(map_->ray, Vec3d{physicalDir.x, physicalDir.y, physicalDir.z});
  const glm::dvec3 v(s[0], s[1], s[2]);
  const double length = glm::length(v);
  // A map that stores a zero or non-finite direction is broken, not merely unlit: say so rather
  // than trace NaN rays.
  if (!(length > 0.0) || !std::isfinite(length))
    throw Error(ErrorCode::InvalidInput,
                "retarget map: the ray map stores no valid direction near (" +
                    std::to_string(physicalDir.x) + ", " + std::to_string(physicalDir.y) + ", " +
                    std::to_string(physicalDir.z) + ")");
  return {v / length, s[3] >= 0.5f};
}

glm::dvec3 ConformalWarp::warpPoint(const glm::dvec3& physicalPoint) const {
  const glm::dvec3 offset = physicalPoint - reference_;
  const double distance = glm::length(offset);
  if (distance == 0.0) return reference_;
  return reference_ + distance * direction(offset);
}

}  // namespace confvis
