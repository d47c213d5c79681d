#include "confvis/conformal/retarget_map.hpp"

#include <utility>

namespace confvis {

namespace {

std::optional<Vec3d> lookup(const CubeMap& map, const Vec3d& dir) {
  const std::array<float, 4> s = sampleBilinear(map, dir);
  if (!(s[3] >= 0.5f)) return std::nullopt;
  const Vec3d v{s[0], s[1], s[2]};
  const double len = norm(v);
  if (!(len > 0.0) || !std::isfinite(len)) return std::nullopt;
  return (1.0 / len) * v;
}

}  // namespace

std::optional<Vec3d> RetargetMap::toVirtual(const Vec3d& physicalDir) const {
  return lookup(ray, physicalDir);
}

std::optional<Vec3d> RetargetMap::toPhysical(const Vec3d& virtualDir) const {
  return lookup(geom, virtualDir);
}

RetargetMap RetargetMap::identity(int resolution, const Vec3d& reference) {
  RetargetMap map;
  map.reference = reference;
  map.ray = CubeMap(resolution);
  fillCubeMap(map.ray, [](const Vec3d& d) { return std::pair{d, true}; });
  map.geom = map.ray;
  return map;
}

}  // namespace confvis
