#pragma once
// Texel-grid helpers for cube maps shared by the bake and the baked-map measurements: a flat
// index over all 6 N^2 texels (face-major, then rows), and 4-neighbours across face edges.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "confvis/base/cube_map.hpp"
#include "confvis/base/vec3.hpp"

namespace confvis::detail {

inline std::size_t texelIndex(CubeFace face, int x, int y, int n) {
  return (static_cast<std::size_t>(face) * n + y) * n + x;
}
inline TexelRef texelAt(std::size_t index, int n) {
  const std::size_t perFace = static_cast<std::size_t>(n) * n;
  const int rem = static_cast<int>(index % perFace);
  return {kCubeFaces[index / perFace], rem % n, rem / n};
}

// Texel (x, y) of `face` with x or y one step off the face: the texel of the neighbouring face
// nearest to its direction.
TexelRef texelAcrossEdge(CubeFace face, int x, int y, int n);

// The texel (x + dx, y + dy) of `face`, where a step off the face continues on the neighbouring
// face (at the texel nearest to the stepped-off texel's direction).
inline TexelRef neighbourTexel(CubeFace face, int x, int y, int dx, int dy, int n) {
  const int nx = x + dx, ny = y + dy;
  if (nx >= 0 && nx < n && ny >= 0 && ny < n) return {face, nx, ny};
  return texelAcrossEdge(face, nx, ny, n);
}

inline constexpr int kNeighbourSteps[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};

// Graph distance (4-neighbours across faces) from every texel to the nearest texel whose mask is
// 0, capped at `cap`; all texels get `cap` when no mask entry is 0.
std::vector<std::uint8_t> distanceToUnmasked(const std::vector<std::uint8_t>& mask, int n,
                                             std::uint8_t cap);

// Normalises `sum` into the RGBA texel. Only a triangle spanning antipodal corners could sum to
// (nearly) zero; its corner stands in then.
inline void writeDirection(float* texel, const Vec3d& sum, const Vec3d& fallback, float alpha) {
  const double length = norm(sum);
  const Vec3d dir = length > 1e-12 ? (1.0 / length) * sum : fallback;
  texel[0] = static_cast<float>(dir.x);
  texel[1] = static_cast<float>(dir.y);
  texel[2] = static_cast<float>(dir.z);
  texel[3] = alpha;
}

// The bake's extension past the covered region (see bake.hpp).
void extendPastBoundary(CubeMap& map, const std::vector<std::uint8_t>& covered);

}  // namespace confvis::detail
