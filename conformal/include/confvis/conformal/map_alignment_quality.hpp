#pragma once
// How a baked map sits on its display, in pixels of the walls (design note §3 step 5): where the
// virtual forward direction lands and whether up stays up there, and how far a display's mirror
// symmetry is broken. Measured by sampling the baked cube maps (RetargetMap lookups), so it
// covers everything from the templates to the bake. Used by the tests and the alignment bench.
#include <cstddef>
#include <optional>
#include <string>

#include "confvis/base/export.hpp"
#include "confvis/base/vec3.hpp"
#include "confvis/conformal/retarget_map.hpp"
#include "confvis/engine/display_config.hpp"

namespace confvis CONFVIS_API {

struct GazeAlignment {
  // The wall point that shows the virtual forward direction (geom's lookup), in the wall's lit
  // rectangle coordinates s (left to right) and t (bottom to top), 0..1.
  std::string wall;
  double s = 0, t = 0;
  // Its distance from the display point straight ahead of the reference point, in pixels of that
  // wall; nullopt where the straight-ahead direction misses the wall (or the display).
  std::optional<double> offsetPixels;
  // At the straight-ahead display point: the angle between the virtual image of the wall's up
  // direction (ray's central difference over a few pixels) and virtual up (+y projected), degrees.
  std::optional<double> upTiltDegrees;
};

// forward: the physical and virtual forward direction (the hemisphere axis, else -z).
// Throws Error(InvalidInput) when the forward direction's content is not on any wall.
GazeAlignment measureGazeAlignment(const RetargetMap& map, const DisplayConfig& config,
                                   const Vec3d& forward);

struct MirrorAsymmetry {
  std::size_t samples = 0;  // sample pairs with both directions lit
  double p50 = 0, p99 = 0, max = 0;  // pixels of the sampled wall
  std::string worstWall;
};

// The mirror through the plane through the reference point with normal `planeNormal`. On every
// wall a grid of samplesPerSide^2 points of its lit rectangle, `margin` (a fraction of its sides)
// away from its edges: the physical direction d and its mirror image d' must get mirrored virtual
// directions, T_ray(d') = mirror(T_ray(d)). The angle between the two is converted to pixels on
// the wall with ray's own scale there (the smaller of its virtual angles per pixel along the
// wall's right and up, from central differences over 1 % of the wall), i.e. how far the content
// would have to move on the wall to be symmetric. Pairs whose mirror image is not lit are skipped.
MirrorAsymmetry measureMirrorAsymmetry(const RetargetMap& map, const DisplayConfig& config,
                                       const Vec3d& planeNormal, int samplesPerSide = 24,
                                       double margin = 0.04);

}  // namespace confvis
