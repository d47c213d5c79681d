#pragma once
// Retarget maps known in closed form, for tests and benchmarks while no baked map is at hand
// (and to check baked maps against): a rigid rotation, and a conformal stand-in for a display
// with its ceiling missing.
#include <glm/glm.hpp>

#include "confvis/base/export.hpp"
#include "confvis/conformal/retarget_map.hpp"

namespace confvis CONFVIS_API {

// T_ray(d) = rotation * d everywhere (a rotation is conformal); T_geom is its inverse. With this
// map W is the rigid rotation about c, so a conformal render equals a plain render whose
// virtual camera is turned by `rotation`.
RetargetMap rotationMap(const glm::dmat3& rotation, int resolution,
                        const glm::dvec3& reference = glm::dvec3(0.0));

// A conformal map of the sphere with the ceiling cap removed: physical directions in the
// ceiling's cone of a cube around c (d.y >= |d.x|, |d.z|) are unlit; elsewhere T_ray is the
// Möbius dilation w -> lambda w of the stereographic coordinate w = (x + i z) / (1 - y) seen from
// the zenith, which pushes directions up towards the zenith for lambda > 1 (the floor's centre
// stays fixed). Virtual content above the walls thus appears near their top edges, like the
// 5-sided CAVE's real map, but with a round instead of a square boundary.
RetargetMap ceilinglessDilationMap(double lambda, int resolution,
                                   const glm::dvec3& reference = glm::dvec3(0.0));
// The dilation itself on a unit direction (exposed for closed-form checks).
glm::dvec3 stereographicDilation(const glm::dvec3& unitDirection, double lambda);

}  // namespace confvis
