#include "packet_tracer.hpp"

#include <cmath>
#include <limits>

namespace confvis::embree {

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

void setRay(RTCRay8& ray, int lane, const glm::vec3& origin, const glm::vec3& direction,
            float tfar) {
  ray.org_x[lane] = origin.x;
  ray.org_y[lane] = origin.y;
  ray.org_z[lane] = origin.z;
  ray.dir_x[lane] = direction.x;
  ray.dir_y[lane] = direction.y;
  ray.dir_z[lane] = direction.z;
  ray.tnear[lane] = 0.0f;
  ray.tfar[lane] = tfar;
  ray.time[lane] = 0.0f;
  ray.mask[lane] = ~0u;
  ray.id[lane] = static_cast<unsigned>(lane);
  ray.flags[lane] = 0;
}

// Copies lane's hit into `hits`; false when the lane missed.
bool recordHit(const RTCRayHit8& rayhit, int lane, PacketHits& hits) {
  if (rayhit.hit.geomID[lane] == RTC_INVALID_GEOMETRY_ID) return false;
  const glm::vec3 direction(rayhit.ray.dir_x[lane], rayhit.ray.dir_y[lane],
                            rayhit.ray.dir_z[lane]);
  const glm::vec3 origin(rayhit.ray.org_x[lane], rayhit.ray.org_y[lane], rayhit.ray.org_z[lane]);
  hits.hit[lane] = true;
  hits.geomID[lane] = rayhit.hit.geomID[lane];
  hits.primID[lane] = rayhit.hit.primID[lane];
  hits.barycentrics[lane] = {rayhit.hit.u[lane], rayhit.hit.v[lane]};
  hits.geometricNormal[lane] = {rayhit.hit.Ng_x[lane], rayhit.hit.Ng_y[lane],
                                rayhit.hit.Ng_z[lane]};
  hits.point[lane] = origin + rayhit.ray.tfar[lane] * direction;
  hits.direction[lane] = direction;
  return true;
}

// How far a retried tail turns: far below a pixel (~1e-3 rad on a CAVE wall), far above float
// rounding of a unit direction (~6e-8).
constexpr float kRetryAngle = 1e-5f;

// `direction` turned by about kRetryAngle, off every axis-aligned plane through it.
glm::vec3 nudged(const glm::vec3& direction) {
  const glm::vec3 helper =
      std::abs(direction.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  const glm::vec3 a = glm::normalize(glm::cross(direction, helper));
  const glm::vec3 b = glm::cross(direction, a);
  return glm::normalize(direction + kRetryAngle * (0.8f * a + 0.6f * b));
}

bool isLoneMiss(const PacketHits& hits, const std::array<bool, kPacketSize>& missed, int lane,
                int count) {
  if (!missed[lane] || count < 2) return false;
  const bool left = lane == 0 || hits.hit[lane - 1];
  const bool right = lane == count - 1 || hits.hit[lane + 1];
  return left && right;
}

}  // namespace

std::uint64_t tracePaths(RTCScene scene, const RayPath* paths, int count, PacketHits& hits) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  std::array<bool, kPacketSize> active{};
  int maxVertices = 0;
  for (int lane = 0; lane < kPacketSize; ++lane) {
    hits.hit[lane] = false;
    active[lane] = lane < count && paths[lane].lit;
    if (active[lane]) maxVertices = std::max(maxVertices, paths[lane].vertexCount);
  }
  std::uint64_t rays = 0;
  hits.retraced = 0;
  for (int segment = 0; segment < maxVertices; ++segment) {
    alignas(32) int valid[kPacketSize];
    alignas(32) RTCRayHit8 rayhit;
    bool any = false;
    for (int lane = 0; lane < kPacketSize; ++lane) {
      valid[lane] = 0;
      if (!active[lane] || segment >= paths[lane].vertexCount) continue;
      const RayPath& path = paths[lane];
      const glm::vec3 origin = path.vertices[segment];
      glm::vec3 direction = path.tail;
      float tfar = kInfinity;
      if (segment + 1 < path.vertexCount) {
        direction = path.vertices[segment + 1] - origin;
        tfar = glm::length(direction);
        if (!(tfar > 0.0f)) continue;  // a zero-length segment cannot hit anything
        direction /= tfar;
      }
      setRay(rayhit.ray, lane, origin, direction, tfar);
      rayhit.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
      rayhit.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
      valid[lane] = -1;
      any = true;
      ++rays;
    }
    if (!any) continue;
    rtcIntersect8(valid, scene, &context, &rayhit);
    for (int lane = 0; lane < kPacketSize; ++lane) {
      if (!valid[lane]) continue;
      if (recordHit(rayhit, lane, hits)) active[lane] = false;
    }
  }
  // Retry lone misses along their tail (they are still `active`: lit, no hit).
  alignas(32) int valid[kPacketSize];
  alignas(32) RTCRayHit8 rayhit;
  for (int lane = 0; lane < kPacketSize; ++lane) {
    valid[lane] = 0;
    if (!isLoneMiss(hits, active, lane, count)) continue;
    const RayPath& path = paths[lane];
    setRay(rayhit.ray, lane, path.vertices[path.vertexCount - 1], nudged(path.tail), kInfinity);
    rayhit.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
    valid[lane] = -1;
    ++hits.retraced;
  }
  if (hits.retraced == 0) return rays;
  rtcIntersect8(valid, scene, &context, &rayhit);
  for (int lane = 0; lane < kPacketSize; ++lane)
    if (valid[lane]) recordHit(rayhit, lane, hits);
  return rays + static_cast<std::uint64_t>(hits.retraced);
}

std::uint64_t traceOcclusion(RTCScene scene, OcclusionPacket& packet) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  alignas(32) int valid[kPacketSize];
  alignas(32) RTCRay8 ray;
  std::uint64_t rays = 0;
  for (int lane = 0; lane < kPacketSize; ++lane) {
    valid[lane] = packet.active[lane] ? -1 : 0;
    packet.occluded[lane] = false;
    if (!packet.active[lane]) continue;
    setRay(ray, lane, packet.origin[lane], packet.direction[lane], packet.distance[lane]);
    ++rays;
  }
  if (rays == 0) return 0;
  rtcOccluded8(valid, scene, &context, &ray);
  // Embree sets tfar to -inf for occluded rays.
  for (int lane = 0; lane < kPacketSize; ++lane)
    if (packet.active[lane]) packet.occluded[lane] = ray.tfar[lane] < 0.0f;
  return rays;
}

}  // namespace confvis::embree
