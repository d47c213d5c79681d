#include "packet_tracer.hpp"

#include <cmath>
#include <cstring>
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

// The fields every camera ray shares, for all lanes (Embree ignores the invalid ones): unbounded,
// no hit yet.
void resetRays(RTCRayHit8& rayhit) {
  for (int lane = 0; lane < kPacketSize; ++lane) {
    rayhit.ray.tnear[lane] = 0.0f;
    rayhit.ray.tfar[lane] = kInfinity;
    rayhit.ray.time[lane] = 0.0f;
    rayhit.ray.mask[lane] = ~0u;
    rayhit.ray.id[lane] = static_cast<unsigned>(lane);
    rayhit.ray.flags[lane] = 0;
    rayhit.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
  }
}

// Copies lane's ray and hit record from one packet into another.
void copyLane(const RTCRayHit8& from, int lane, RTCRayHit8& to) {
  to.ray.org_x[lane] = from.ray.org_x[lane];
  to.ray.org_y[lane] = from.ray.org_y[lane];
  to.ray.org_z[lane] = from.ray.org_z[lane];
  to.ray.dir_x[lane] = from.ray.dir_x[lane];
  to.ray.dir_y[lane] = from.ray.dir_y[lane];
  to.ray.dir_z[lane] = from.ray.dir_z[lane];
  to.ray.tfar[lane] = from.ray.tfar[lane];
  to.hit.u[lane] = from.hit.u[lane];
  to.hit.v[lane] = from.hit.v[lane];
  to.hit.Ng_x[lane] = from.hit.Ng_x[lane];
  to.hit.Ng_y[lane] = from.hit.Ng_y[lane];
  to.hit.Ng_z[lane] = from.hit.Ng_z[lane];
  to.hit.geomID[lane] = from.hit.geomID[lane];
  to.hit.primID[lane] = from.hit.primID[lane];
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

// Zero barycentrics, normal, direction and hit distance on the lanes without a hit, so shading
// can run branch-free over all eight lanes.
void clearMissedLanes(PacketHits& hits) {
  RTCRayHit8& r = hits.rayhit;
  for (int lane = 0; lane < kPacketSize; ++lane) {
    if (hits.hit[lane]) continue;
    r.ray.org_x[lane] = r.ray.org_y[lane] = r.ray.org_z[lane] = 0.0f;
    r.ray.dir_x[lane] = r.ray.dir_y[lane] = r.ray.dir_z[lane] = 0.0f;
    r.ray.tfar[lane] = 0.0f;
    r.hit.u[lane] = r.hit.v[lane] = 0.0f;
    r.hit.Ng_x[lane] = r.hit.Ng_y[lane] = r.hit.Ng_z[lane] = 0.0f;
  }
}

// Lanes are pixels in rows of `columns` (PacketSamples): a lone miss has hits at every
// neighbouring pixel of the packet, beside it in its row and above or below it.
bool isLoneMiss(const PacketHits& hits, const std::array<bool, kPacketSize>& missed, int lane,
                int count, int columns) {
  if (!missed[lane]) return false;
  const int column = lane % columns;
  int neighbours = 0;
  bool allHit = true;
  const auto neighbour = [&](int other) {
    ++neighbours;
    allHit = allHit && hits.hit[other];
  };
  if (column > 0) neighbour(lane - 1);
  if (column + 1 < columns) neighbour(lane + 1);
  if (lane + columns < count) neighbour(lane + columns);
  if (lane >= columns) neighbour(lane - columns);
  return neighbours > 0 && allHit;
}

RTCIntersectContext coherentContext() {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  return context;
}

// Traces the lone misses among `missed` (lanes traced without a hit) once more from origins[lane]
// along tails[lane] turned by kRetryAngle; records their hits. Returns the number retried.
int retryLoneMisses(RTCScene scene, int count, int columns,
                    const std::array<bool, kPacketSize>& missed,
                    const std::array<glm::vec3, kPacketSize>& origins,
                    const std::array<glm::vec3, kPacketSize>& tails, PacketHits& hits) {
  alignas(32) int valid[kPacketSize];
  alignas(32) RTCRayHit8 retry;
  int retried = 0;
  for (int lane = 0; lane < kPacketSize; ++lane) {
    valid[lane] = 0;
    if (!isLoneMiss(hits, missed, lane, count, columns)) continue;
    setRay(retry.ray, lane, origins[lane], nudged(tails[lane]), kInfinity);
    retry.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
    retry.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
    valid[lane] = -1;
    ++retried;
  }
  if (retried == 0) return 0;
  RTCIntersectContext context = coherentContext();
  rtcIntersect8(valid, scene, &context, &retry);
  for (int lane = 0; lane < kPacketSize; ++lane)
    if (valid[lane] && retry.hit.geomID[lane] != RTC_INVALID_GEOMETRY_ID) {
      copyLane(retry, lane, hits.rayhit);
      hits.hit[lane] = true;
    }
  return retried;
}

// traceStraight's first step: the lanes to trace counted, the rays' other fields set. Returns
// the count.
int prepareStraight(PacketHits& hits) {
  hits.retraced = 0;
  int rays = 0;
  for (int lane = 0; lane < kPacketSize; ++lane) {
    hits.hit[lane] = false;
    rays += hits.valid[lane] != 0;
  }
  if (rays > 0) resetRays(hits.rayhit);
  return rays;
}

// traceStraight's last step, after the intersection: hit flags, lone misses retried, missed
// lanes cleared. Returns the rays cast, retries included.
std::uint64_t finishStraight(RTCScene scene, int rays, int count, int columns, PacketHits& hits) {
  if (rays == 0) {
    clearMissedLanes(hits);
    return 0;
  }
  std::array<bool, kPacketSize> missed{};
  bool anyMissed = false;
  // The flags are stored as one 8-byte word: shading reads them so, and a load waits for the
  // stores it overlaps to reach the cache unless one store covers it (store-to-load forwarding).
  std::uint64_t hitFlags = 0;
  for (int lane = 0; lane < kPacketSize; ++lane) {
    const bool hit = hits.valid[lane] && hits.rayhit.hit.geomID[lane] != RTC_INVALID_GEOMETRY_ID;
    hitFlags |= static_cast<std::uint64_t>(hit) << (8 * lane);
    missed[lane] = hits.valid[lane] && !hit;
    anyMissed |= missed[lane];
  }
  static_assert(sizeof(hits.hit) == sizeof hitFlags);
  std::memcpy(hits.hit.data(), &hitFlags, sizeof hitFlags);
  if (anyMissed) {
    std::array<glm::vec3, kPacketSize> origins{}, tails{};
    for (int lane = 0; lane < kPacketSize; ++lane)
      if (missed[lane]) {
        origins[lane] = {hits.rayhit.ray.org_x[lane], hits.rayhit.ray.org_y[lane],
                         hits.rayhit.ray.org_z[lane]};
        tails[lane] = hits.direction(lane);
      }
    hits.retraced = retryLoneMisses(scene, count, columns, missed, origins, tails, hits);
  }
  clearMissedLanes(hits);
  return static_cast<std::uint64_t>(rays + hits.retraced);
}

// The rays of `half` into lanes offset .. offset + 7 of `wide` (RTCRay8 and RTCRay16 are
// structures of arrays with the same fields in the same order).
void packRays(const RTCRay8& half, int offset, RTCRay16& wide) {
  const auto put = [offset](const auto& from, auto& to) {
    std::memcpy(to + offset, from, sizeof from);
  };
  put(half.org_x, wide.org_x), put(half.org_y, wide.org_y), put(half.org_z, wide.org_z);
  put(half.tnear, wide.tnear);
  put(half.dir_x, wide.dir_x), put(half.dir_y, wide.dir_y), put(half.dir_z, wide.dir_z);
  put(half.time, wide.time), put(half.tfar, wide.tfar), put(half.mask, wide.mask);
  put(half.id, wide.id), put(half.flags, wide.flags);
}

// What rtcIntersect16 wrote for lanes offset .. offset + 7 back into `half`.
void unpackHits(const RTCRayHit16& wide, int offset, RTCRayHit8& half) {
  const auto get = [offset](const auto& from, auto& to) {
    std::memcpy(to, from + offset, sizeof to);
  };
  get(wide.ray.tfar, half.ray.tfar);
  get(wide.hit.Ng_x, half.hit.Ng_x), get(wide.hit.Ng_y, half.hit.Ng_y);
  get(wide.hit.Ng_z, half.hit.Ng_z), get(wide.hit.u, half.hit.u), get(wide.hit.v, half.hit.v);
  get(wide.hit.primID, half.hit.primID), get(wide.hit.geomID, half.hit.geomID);
  get(wide.hit.instID[0], half.hit.instID[0]);
}

// The packet's prepared rays traced with one rtcIntersect8.
void intersect8(RTCScene scene, PacketHits& hits) {
  RTCIntersectContext context = coherentContext();
  rtcIntersect8(hits.valid.data(), scene, &context, &hits.rayhit);
}

}  // namespace

std::uint64_t traceStraight(RTCScene scene, int count, int columns, PacketHits& hits) {
  const int rays = prepareStraight(hits);
  if (rays > 0) intersect8(scene, hits);
  return finishStraight(scene, rays, count, columns, hits);
}

std::uint64_t traceStraightPair(RTCScene scene, const std::array<int, 2>& count,
                                const std::array<int, 2>& columns,
                                std::array<PacketHits, 2>& hits, bool native16) {
  const std::array<int, 2> rays = {prepareStraight(hits[0]), prepareStraight(hits[1])};
  if (native16 && rays[0] > 0 && rays[1] > 0) {
    alignas(64) std::array<int, 2 * kPacketSize> valid;
    alignas(64) RTCRayHit16 wide;
    for (int half = 0; half < 2; ++half) {
      std::memcpy(valid.data() + half * kPacketSize, hits[half].valid.data(), sizeof hits[half].valid);
      packRays(hits[half].rayhit.ray, half * kPacketSize, wide.ray);
      std::memcpy(wide.hit.geomID + half * kPacketSize, hits[half].rayhit.hit.geomID,
                  sizeof hits[half].rayhit.hit.geomID);
      std::memcpy(wide.hit.instID[0] + half * kPacketSize, hits[half].rayhit.hit.instID[0],
                  sizeof hits[half].rayhit.hit.instID[0]);
    }
    RTCIntersectContext context = coherentContext();
    rtcIntersect16(valid.data(), scene, &context, &wide);
    for (int half = 0; half < 2; ++half) unpackHits(wide, half * kPacketSize, hits[half].rayhit);
  } else {
    for (int half = 0; half < 2; ++half)
      if (rays[half] > 0) intersect8(scene, hits[half]);
  }
  return finishStraight(scene, rays[0], count[0], columns[0], hits[0]) +
         finishStraight(scene, rays[1], count[1], columns[1], hits[1]);
}

std::uint64_t tracePaths(RTCScene scene, const RayPath* paths, int count, int columns,
                         PacketHits& hits) {
  RTCIntersectContext context = coherentContext();
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
      if (!valid[lane] || rayhit.hit.geomID[lane] == RTC_INVALID_GEOMETRY_ID) continue;
      copyLane(rayhit, lane, hits.rayhit);
      hits.hit[lane] = true;
      active[lane] = false;
    }
  }
  // Lanes still `active` are lit and missed; retry the lone ones along their tail.
  std::array<glm::vec3, kPacketSize> origins{}, tails{};
  for (int lane = 0; lane < kPacketSize; ++lane)
    if (active[lane]) {
      origins[lane] = paths[lane].vertices[paths[lane].vertexCount - 1];
      tails[lane] = paths[lane].tail;
    }
  hits.retraced = retryLoneMisses(scene, count, columns, active, origins, tails, hits);
  clearMissedLanes(hits);
  return rays + static_cast<std::uint64_t>(hits.retraced);
}

std::uint64_t traceOcclusion(RTCScene scene, OcclusionPacket& packet) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);  // incoherent: hemisphere directions
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
