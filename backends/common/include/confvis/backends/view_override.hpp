#pragma once
// Application-supplied view and projection for a wall's eye (RenderSettings::views), instead of
// the off-axis view confvis computes from the head pose (WallView): for applications that own
// their camera model (a tracking system's own calibration, a recorded camera path, a test).
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "confvis/engine/view.hpp"
#include "confvis/base/export.hpp"
#include "confvis/engine/viewer.hpp"

namespace confvis CONFVIS_API {

struct ViewOverride {
  std::string wall;
  Eye eye = Eye::Center;
  // Physical (display) frame -> eye space: the eye at the origin looking down -z, as
  // WallView::view. Must be an invertible affine transform.
  glm::dmat4 view{1.0};
  // Eye space -> Vulkan clip space (x right, y DOWN, both -1..1 across the wall's output
  // image), as WallView::projectionVulkan / projectionVulkanReverseZ. The backends use its x,
  // y and w rows; depth is their own (Vulkan: reverse-Z with the near plane at 1e-5 of the
  // eye's distance to the wall plane; Embree: rays from the eye), so any depth row will do.
  glm::dmat4 projection{1.0};
};

// The override of `wall`'s `eye`, or null.
const ViewOverride* findViewOverride(const std::vector<ViewOverride>& views,
                                     const std::string& wall, Eye eye);

// The projection with the depth row replaced by (0, 0, 0, near): clip depth near / w, reverse-Z
// (WallView::projectionVulkanReverseZ's depth), the same matrix when it already is one.
glm::dmat4 withReverseDepth(const glm::dmat4& projection, double near);

// The override's eye position in the physical frame (inverse(view) applied to the origin).
glm::dvec3 overrideEyePosition(const ViewOverride& view);

// World-space ray directions of an override, affine in the pixel position: pixel-space point
// (px, py) of a wall image `width` x `height` (py = 0 at the top edge, as WallView::rayDirection)
// looks along base + px stepX + py stepY, scaled to reach eye-space depth `depth` at t = 1.
struct OverrideRays {
  glm::dvec3 eye, base, stepX, stepY;
};
OverrideRays overrideRays(const ViewOverride& view, double width, double height, double depth);

// Error(InvalidInput) naming the wall and eye: a non-finite matrix, a view that is not an
// invertible affine transform, a projection whose x, y, w rows leave the rays undefined, a wall
// the config does not have, or a wall and eye overridden twice.
void checkViewOverrides(const std::vector<ViewOverride>& views,
                        const std::vector<std::string>& knownWalls);

}  // namespace confvis
