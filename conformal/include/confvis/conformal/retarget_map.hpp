#pragma once
// The baked conformal map of a display (design note §3 step 7): two direction cube maps around
// the reference point c, in confvis's EXR cube layout (confvis/base/cube_map.hpp).
//   ray:  indexed by a physical direction d (from c), stores the virtual direction T_ray(d) in RGB;
//         alpha 1 where d has a lit display behind it, 0 elsewhere.
//   geom: indexed by a virtual direction v, stores the physical direction T_geom(v) = T_ray^-1(v);
//         alpha 1 where v lies in the source field S, 0 elsewhere (e.g. outside a hemisphere).
// Invalid texels (alpha 0) still hold a direction: the bake extends the map past its boundary
// (extrapolated linearly for three texels, then the nearest value), so bilinear lookups next to
// the boundary never blend in garbage.
#include <optional>

#include "confvis/base/cube_map.hpp"
#include "confvis/base/export.hpp"
#include "confvis/base/vec3.hpp"

namespace confvis CONFVIS_API {

// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
// toVirtual and toPhysical only read: a map in use by a renderer may be shared by many.
struct RetargetMap {
  glm::dvec3 reference{0.0};  // c, metres, physical frame
  CubeMap ray;
  CubeMap geom;

  // Bilinear lookup in `ray`, renormalised. nullopt where the interpolated alpha is below 0.5
  // (no display behind d). Throws Error(InvalidInput) for a zero or non-finite direction.
  std::optional<glm::dvec3> toVirtual(const glm::dvec3& physicalDir) const;
  // Lookup in `geom`, renormalised. nullopt where v is outside the source field. Bilinear, except
  // where the footprint straddles the source's cut (geom jumps there): the texels across the cut
  // are replaced by extrapolations of v's side, so v keeps its own side of the display.
  std::optional<glm::dvec3> toPhysical(const glm::dvec3& virtualDir) const;

  int resolution() const { return ray.faceSize; }

  // The identity map of a 6-sided CAVE (both maps store their own texel direction, alpha 1):
  // what a complete display bakes to, and a stand-in for tests of the renderers.
  static RetargetMap identity(int resolution, const glm::dvec3& reference = {});
};

// Fills every texel of `map` with f(unit direction of the texel centre) -> (direction, valid).
// Used by the bake and by tests that build analytic maps.
template <class F>
void fillCubeMap(CubeMap& map, F&& f) {
  const int n = map.faceSize;
  for (CubeFace face : kCubeFaces) {
    ImageRGBA& img = map.face(face);
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const auto [dir, valid] = f(normalized(texelDirection(face, x, y, n)));
        float* p = img.at(x, y);
        p[0] = static_cast<float>(dir.x);
        p[1] = static_cast<float>(dir.y);
        p[2] = static_cast<float>(dir.z);
        p[3] = valid ? 1.0f : 0.0f;
      }
  }
}

}  // namespace confvis
