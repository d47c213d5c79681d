#pragma once
// The Möbius alignment of a display map's two disks (design note §3 step 5): each disk is moved
// by a disk automorphism e^{it}(z - a)/(1 - conj(a) z) so that its anchor direction goes to 0 and
// the "up" tangent there points along +i. With the source anchored at the forward direction and
// the target at the display point straight ahead of the reference point, T_ray = phi_S^-1 o
// phi_D sends the straight-ahead display point to the forward direction and keeps up up there:
// the three real parameters of the automorphism are exactly these constraints. Nothing else is
// pinned, so a display with a mirror symmetry through the reference point (one that keeps the
// forward direction and up, or reverses up) gets a mirror-symmetric map, as far as its meshes
// are symmetric.
//
// Traded: the seed aligned three cut leaves with the display corners they stand for (markers at
// 1, i, -1). Here no boundary point is pinned, so a cut leaf of a sphere source lands on the
// display's rim near, not at, its display corner (measured in bake.json's "alignment" stats as
// "leaf_offset_degrees"); the rim still maps onto the cut, each flap onto the wall edges around
// it. Where a display's symmetry fixes the leaves (cave5's four ceiling corners under quarter
// turns) the two coincide.
#include <array>
#include <complex>
#include <string>

#include <nlohmann/json.hpp>

#include "confvis/base/vec3.hpp"
#include "confvis/conformal/display_map.hpp"

namespace confvis::detail {

// A direction located in a sphere mesh (chord triangles, as the bake rasterises them).
struct SphereLocation {
  int triangle = -1;  // -1: not covered
  std::array<double, 3> barycentric{};
};
SphereLocation locateDirection(const SphereDiskMesh& mesh, const Vec3d& direction);

// The disk point of a located direction (the piecewise-linear map in the chord's coordinates).
std::complex<double> diskPoint(const SphereDiskMesh& mesh, const SphereLocation& at);

// "Up" in the tangent plane at `direction`: +y projected; looking (nearly) straight down, -z
// (the top of the picture towards the forward direction), straight up, +z.
Vec3d upAt(const Vec3d& direction);

// Anchors the source at `forward` and the target at the display point straight ahead (the same
// direction), or, where the display does not cover it, at the display's centre of directions;
// moves both disks of `map` and returns what it did for bake.json (anchors, the "up" step, the
// cut leaves' offsets from their display corners). Throws Error(InvalidInput) naming the display
// when neither target anchor lies inside the display, or the forward direction lies on the
// source's rim (its cut).
nlohmann::json alignAtForward(DisplayMap& map, const Vec3d& forward, const std::string& name);

}  // namespace confvis::detail
