#pragma once
// Conformal drawing bends every triangle by the warp about its centre c; the pre-pass follows
// the bend with at most one tessellation patch a triangle, and its drop rules (made for pieces
// torn across the source's cut) read a triangle spanning tens of degrees seen from c as torn. A
// large quad next to the viewer or a ground plane under them is such a triangle. So before the
// warp the backend splits every triangle whose corners lie more than a bound apart seen from c,
// until no edge does (issue 23).
//
// The split is conforming: each edge is cut once, at points spaced evenly in the angle it
// subtends at c (its neighbour across the edge cuts it at the same points), and each triangle is
// then bisected at its most-cut edge's middle point towards the opposite corner until none of
// its edges is cut (longest-edge bisection: the pieces stay well shaped). New vertices carry the
// position, normal and uv interpolated linearly along their edge, so the pieces shade as the
// triangle did.
#include <cstddef>

#include <glm/glm.hpp>

#include "confvis/engine/scene.hpp"

namespace confvis::vulkan {

// Whether some triangle of `scene` has two corners more than `maxDegrees` apart seen from
// `centre` (a corner at the centre itself has no direction and is never apart: no split moves it).
bool hasWideTriangles(const Scene& scene, const glm::dvec3& centre, double maxDegrees);

struct WideTriangleSplit {
  Scene scene;
  std::size_t trianglesSplit = 0;  // triangles of the input cut into pieces
};

// `scene` with every triangle cut until no edge spans more than `maxDegrees` seen from `centre`
// (edges through the centre's line of sight into at most kMaxEdgePieces pieces, linearly).
WideTriangleSplit splitWideTriangles(const Scene& scene, const glm::dvec3& centre,
                                     double maxDegrees);

inline constexpr int kMaxEdgePieces = 256;

}  // namespace confvis::vulkan
