#pragma once
// How a display map is evaluated between the vertices of its meshes (issue 22, points 2 and 3).
//
// Linear: inside each chord triangle the map is linear between the vertices' disk positions
// (barycentric), so straight virtual lines turn where they cross element boundaries (first order
// in the edge length: cave5 at 20 cm, kink p99 ~21 degrees).
// Mobius: per-vertex Möbius blending. Each vertex j carries a Möbius transformation M_j, fitted
// (least squares, through the vertex itself) to the discrete map on its one-ring: from the
// sphere (stereographic chart at the vertex) to the disk, and its exact inverse from the disk to
// the sphere. Inside a triangle the three corners' maps are blended with the weights
// b_j^2 / (b0^2 + b1^2 + b2^2) of the barycentric coordinates b: continuous across edges (an
// edge's points blend only its two vertices, with the same weights from both sides), exact where
// the discrete map is one Möbius map, and it turns straight lines by O(h^2..h^3) instead of O(h).
// At a singular boundary corner (its angle on the sphere and in the disk polygon differ by more
// than 0.2 rad: a display corner, a cut leaf, a copy of the cut's centre) the map behaves like a
// power of the distance, so that vertex's chart is first raised to the power
// disk angle / sphere angle.
// Where the blend of a triangle folds (its Jacobian changes sign: next to a singular corner on a
// coarse mesh, where the neighbours' Möbius maps cannot follow the corner's power law), that
// triangle's corners and their neighbours use the linear map instead (checked when the blend is
// built), so a Möbius bake never turns a triangle over where the linear one does not.
// The disk -> sphere blend is not the exact inverse of the sphere -> disk blend: T_ray and
// T_geom are inverse to the interpolation's error (well below a pixel at 20 cm edges).
// Measured on cave5 in conformal/README.md ("Smooth interpolation"); it costs ~2x the linear
// bake's CPU, so it is not the live default (kDefaultMapInterpolation, the `fast` preset); the
// offline `accurate` preset (bake_preset.hpp) uses it.
#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {

enum class MapInterpolation { Linear, Mobius };

// What bakes and evaluators use unless told otherwise.
inline constexpr MapInterpolation kDefaultMapInterpolation = MapInterpolation::Linear;

}  // namespace confvis
