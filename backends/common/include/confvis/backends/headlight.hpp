#pragma once
// Where the headlight of an eye sits, shared by both backends so that they light a scene alike
// (Lambert from a point light there, two-sided).
#include <glm/glm.hpp>

#include "confvis/base/export.hpp"
#include "confvis/backends/render_backend.hpp"
#include "confvis/engine/display_config.hpp"

namespace confvis CONFVIS_API {

// Where the headlight of an eye at `eye` (physical frame) sits in the virtual world in conformal
// mode: the start of its virtual rays, c + |e - c| T_ray(dir(e - c)), carried into the world by
// the camera; plain mode: pass map = nullptr for the eye itself. For the eye at c, and for every
// straight ray that starts there, a point light here lights as a light along the ray does.
glm::dvec3 headlightPosition(const glm::dvec3& eye, const DisplayConfig& config,
                             const RetargetMap* map, const VirtualCamera& camera);

}  // namespace confvis
