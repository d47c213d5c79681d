#include "clearance.hpp"

#include <embree3/rtcore.h>

#include <cmath>

namespace confvis::embree {

glm::vec3 closestPointOnTriangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b,
                                 const glm::vec3& c) {
  const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
  const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0f && d2 <= 0.0f) return a;
  const glm::vec3 bp = p - b;
  const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0f && d4 <= d3) return b;
  const float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return a + (d1 / (d1 - d3)) * ab;
  const glm::vec3 cp = p - c;
  const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0f && d5 <= d6) return c;
  const float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return a + (d2 / (d2 - d6)) * ac;
  const float va = d3 * d6 - d5 * d4;
  if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const float denominator = 1.0f / (va + vb + vc);
  return a + ab * (vb * denominator) + ac * (vc * denominator);
}

namespace {

bool shrinkToTriangle(RTCPointQueryFunctionArguments* args) {
  const auto& scene = *static_cast<const Scene*>(args->userPtr);
  const Mesh& mesh = scene.meshes[args->geomID];
  const glm::uvec3 t = mesh.triangles[args->primID];
  const glm::vec3 p(args->query->x, args->query->y, args->query->z);
  const float distance = glm::length(
      p - closestPointOnTriangle(p, mesh.positions[t.x], mesh.positions[t.y], mesh.positions[t.z]));
  if (!(distance < args->query->radius)) return false;
  args->query->radius = distance;
  return true;  // the query's radius shrank
}

}  // namespace

double clearance(const EmbreeScene& scene, const glm::vec3& point, float radius) {
  RTCPointQuery query;
  query.x = point.x;
  query.y = point.y;
  query.z = point.z;
  query.time = 0.0f;
  query.radius = radius;
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(scene.handle(), &query, &context, shrinkToTriangle,
                const_cast<Scene*>(&scene.scene()));
  return query.radius;
}

}  // namespace confvis::embree
