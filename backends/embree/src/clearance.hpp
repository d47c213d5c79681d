#pragma once
// How far the scene keeps from a point: the radius of the empty ball around the warp's centre.
// Exact stereo rays bend only near the centre (W is homogeneous about it), so the bent part of
// every eye ray lies in a small ball there; where the scene keeps out of that ball the bent part
// cannot hit anything, and only the straight rest of the ray needs tracing (camera_rays.hpp).
#include <glm/glm.hpp>

#include "confvis/backends/embree/embree_scene.hpp"

namespace confvis::embree {

// The distance from `point` to the nearest triangle of `scene`, or `radius` where none lies
// closer than that (an Embree point query over the BVH: cost grows with the triangles within
// `radius` only).
double clearance(const EmbreeScene& scene, const glm::vec3& point, float radius);

// The closest point of triangle (a, b, c) to p (Ericson, Real-Time Collision Detection 5.1.5).
glm::vec3 closestPointOnTriangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b,
                                 const glm::vec3& c);

}  // namespace confvis::embree
