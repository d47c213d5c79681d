#pragma once
// The conformal map as a warp of physical space (design note §5), shared by every backend:
//   F(d)  = T_ray(d), the virtual direction shown at physical direction d (seen from c);
//   W(p)  = c + |p - c| F(dir(p)), which carries a physical point to the virtual point drawn there.
// W is homogeneous about c (W(c + s x) = c + s (W(c + x) - c) for s > 0), so the image of a
// straight physical eye ray bends only where it passes close to c.
#include <array>
#include <cstdint>

#include <glm/glm.hpp>

#include "confvis/base/export.hpp"
#include "confvis/conformal/retarget_map.hpp"

namespace confvis CONFVIS_API {

// Folds `word` into `hash` with splitmix64's finaliser (every input bit reaches every output
// bit), for fingerprints of maps and the caches keyed by them.
std::uint64_t mixHash(std::uint64_t hash, std::uint64_t word);
std::uint64_t mixHash(std::uint64_t hash, double value);

// A hash (mixHash) of a cube map's texels, its size and a reference point: identifies a map for
// caches of values derived from it (once per frame: about 1 ms for 256^2 texels a face).
std::uint64_t fingerprintCubeMap(const CubeMap& map, const glm::dvec3& reference);

// Thread-safety: immutable once built (the map it refers to must not change while it lives);
// its const functions may be called from any number of threads at once.
class ConformalWarp {
 public:
  // Checks the map once (well-formed faces, finite reference). Keeps a reference to `map`.
  explicit ConformalWarp(const RetargetMap& map);

  struct Lookup {
    glm::dvec3 direction;  // F(d), unit; defined everywhere (the bake extends it past the edge)
    bool lit;              // a lit display lies behind d (alpha >= 0.5)
    float alpha;           // the map's bilinearly interpolated alpha
  };
  // One bilinear lookup of the ray map; d need not be unit but must be non-zero and finite.
  Lookup lookup(const glm::dvec3& physicalDir) const;
  glm::dvec3 direction(const glm::dvec3& physicalDir) const { return lookup(physicalDir).direction; }
  // The physical directions (from c, through texel centres) of the lit texels (alpha >= 0.5)
  // among the four of physicalDir's bilinear footprint; returns how many. Beyond a face edge a
  // texel is the neighbouring face's texel nearest its centre's direction.
  int litFootprint(const glm::dvec3& physicalDir, std::array<glm::dvec3, 4>& directions) const;
  // W(p); W(c) = c.
  glm::dvec3 warpPoint(const glm::dvec3& physicalPoint) const;
  const glm::dvec3& reference() const { return reference_; }
  const RetargetMap& map() const { return *map_; }
  // A hash (mixHash) of the ray map's texels and the reference point: identifies a map for
  // caches of values derived from it.
  std::uint64_t fingerprint() const;

 private:
  const RetargetMap* map_;
  glm::dvec3 reference_;
};

}  // namespace confvis
