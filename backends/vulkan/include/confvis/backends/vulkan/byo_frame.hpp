#pragma once
// Bring-your-own Vulkan (issue 25): the per-frame values an application's own warp pipeline
// needs, computed exactly as the confvis Vulkan backend computes them for itself
// (src/frame_plan.cpp calls these): each wall's error angles (the tessellation and culling
// bounds, radians), the navigation transform, the walls' reverse-Z projections and the
// conformal headlight. Pure functions; thread-safe.
#include <cstdint>

#include <glm/glm.hpp>

#include "confvis/base/export.hpp"
#include "confvis/backends/headlight.hpp"
#include "confvis/backends/render_backend.hpp"

namespace confvis CONFVIS_API {
namespace vulkan CONFVIS_API {

struct WarpTolerances {
  // A bent edge is subdivided until its drawn polyline is within this many pixels of the exact
  // warped curve (VulkanOptions::tessellationErrorPixels).
  double errorPixels = 0.5;
  // Longest segment of a subdivided edge, degrees (VulkanOptions::maxSegmentDegrees).
  double maxSegmentDegrees = 20.0;
};

// A wall's bounds for the warp, all angles in radians seen from the warp centre c (the map's
// reference point). They are the xyz of `View::params` in the warp's tessellation stages
// (confvis_render_common.glsl: x = errorAngle, y = maxSegmentAngle, z = cutGapAngle, w = 1 to
// tessellate), and the conformal pre-pass takes its thresholds from them.
struct WallWarpBounds {
  // The smallest angle a pixel of the wall (at the rendered resolution) subtends at c.
  double pixelAngle = 0.0;
  // errorPixels * pixelAngle: the largest bend (angle between a drawn segment and the exact
  // warped curve) an edge may keep undivided; the tessellation control shader's level and the
  // pre-pass's flat/tessellated decision use it.
  double errorAngle = 0.0;
  // maxSegmentDegrees in radians.
  double maxSegmentAngle = 0.0;
  // 4 * pixelAngle: the smallest gap the geometry shader reads as a tear across the cut (pieces
  // bigger than this that are stretched or torn are dropped).
  double cutGapAngle = 0.0;
};

// `width` x `height`: the pixels the wall is rendered at (its lit rectangle). Throws
// Error(InvalidInput) for a zero size.
WallWarpBounds wallWarpBounds(const Wall& wall, std::uint32_t width, std::uint32_t height,
                              const glm::dvec3& warpCentre, const WarpTolerances& tolerances = {});

// World (virtual) -> physical frame for a navigating camera: a world point x is drawn at
// config.reference + R^T (x - camera.position) (`Frame::worldToPhysical` of the shaders).
glm::dmat4 worldToPhysical(const DisplayConfig& config, const VirtualCamera& camera);

// The wall's off-axis view-projection for an eye at `eye` (physical frame) in Vulkan clip space,
// reverse-Z without a far plane (depth = near / distance: clear depth to 0, compare GREATER),
// the near plane 1e-5 of the eye's distance to the wall (`View::viewProj`). Throws
// Error(InvalidInput) where the eye cannot see the wall.
glm::dmat4 wallViewProjection(const Wall& wall, const glm::dvec3& eye);

// Where the headlight of an eye sits (`View::eyeVirtual`): confvis/backends/headlight.hpp, the
// same for both backends.
using confvis::headlightPosition;

}  // namespace vulkan
}  // namespace confvis
