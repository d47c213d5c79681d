#include "confvis/conformal/retarget_map.hpp"

#include <limits>
#include <utility>

#include "cut_aware_lookup.hpp"

namespace confvis {

std::optional<Vec3d> RetargetMap::toVirtual(const Vec3d& physicalDir) const {
  const std::array<float, 4> s = sampleBilinear(ray, physicalDir);
  if (!(s[3] >= 0.5f)) return std::nullopt;
  const Vec3d v{s[0], s[1], s[2]};
  const double len = norm(v);
  if (!(len > 0.0) || !std::isfinite(len)) return std::nullopt;
  return (1.0 / len) * v;
}

std::optional<Vec3d> RetargetMap::toPhysical(const Vec3d& virtualDir) const {
  const detail::OneSidedSample sample = detail::lookupGeomAcrossCut(*this, virtualDir);
  if (!(sample.alpha >= 0.5f)) return std::nullopt;
  return sample.direction;
}

namespace detail {

OneSidedSample lookupGeomAcrossCut(const RetargetMap& map, const Vec3d& virtualDir) {
  sampleBilinear(map.geom, virtualDir);  // validates the map and the direction
  const double jump = jumpChord(map.geom.faceSize);
  const OneSidedSample nearSide = *sampleOneSide(map.geom, virtualDir, 0, jump);
  if (!nearSide.straddles) return nearSide;
  const std::optional<OneSidedSample> farSide = sampleOneSide(map.geom, virtualDir, 1, jump);
  if (!farSide) return nearSide;
  // Within a texel of the cut the nearest texel's side can be the wrong one. The right side's
  // physical direction lies on the display (ray valid there) and ray takes it back to v; the
  // other side's lands past the rim, unless both land within ray's own resolution of it.
  auto mismatch = [&](const OneSidedSample& s) {
    const std::array<float, 4> back = sampleBilinear(map.ray, s.direction);
    if (!(back[3] >= 0.5f)) return std::numeric_limits<double>::infinity();
    return angleBetween(Vec3d{back[0], back[1], back[2]}, virtualDir);
  };
  return mismatch(*farSide) < mismatch(nearSide) ? *farSide : nearSide;
}

}  // namespace detail

RetargetMap RetargetMap::identity(int resolution, const Vec3d& reference) {
  RetargetMap map;
  map.reference = reference;
  map.ray = CubeMap(resolution);
  fillCubeMap(map.ray, [](const Vec3d& d) { return std::pair{d, true}; });
  map.geom = map.ray;
  return map;
}

}  // namespace confvis
