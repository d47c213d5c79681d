#pragma once
// Tracing in packets of 8 (rtcIntersect8 / rtcOccluded8): straight camera rays written straight
// into the packet, bent paths segment by segment, and shadow-style occlusion rays for ambient
// occlusion.
#include <embree3/rtcore.h>

#include <array>
#include <cstdint>

#include <glm/glm.hpp>

#include "camera_rays.hpp"

namespace confvis::embree {

// One packet of camera samples. The camera fills the rays; tracing fills the hits. Per lane,
// rayhit holds the ray (segment) that ended the path: unit direction, tfar at the hit, and
// Embree's hit record, so shading reads Embree's structure-of-arrays layout as it is.
struct PacketHits {
  alignas(32) RTCRayHit8 rayhit;
  alignas(32) std::array<int, kPacketSize> valid{};  // traceStraight input: -1 = trace the lane
  std::array<bool, kPacketSize> hit{};
  int retraced = 0;  // lanes traced a second time (see traceStraight)

  void setStraightRay(int lane, const glm::vec3& origin, const glm::vec3& unitDirection) {
    rayhit.ray.org_x[lane] = origin.x;
    rayhit.ray.org_y[lane] = origin.y;
    rayhit.ray.org_z[lane] = origin.z;
    rayhit.ray.dir_x[lane] = unitDirection.x;
    rayhit.ray.dir_y[lane] = unitDirection.y;
    rayhit.ray.dir_z[lane] = unitDirection.z;
    valid[lane] = -1;
  }
  glm::vec3 direction(int lane) const {
    return {rayhit.ray.dir_x[lane], rayhit.ray.dir_y[lane], rayhit.ray.dir_z[lane]};
  }
  glm::vec3 point(int lane) const {  // where the lane hit
    const glm::vec3 origin(rayhit.ray.org_x[lane], rayhit.ray.org_y[lane],
                           rayhit.ray.org_z[lane]);
    return origin + rayhit.ray.tfar[lane] * direction(lane);
  }
};

// Traces the lanes whose `valid` is set (origin and unit direction already in hits.rayhit, see
// setStraightRay) as unbounded rays. The packet's `count` lanes are pixels in rows of `columns`
// (PacketSamples). A lane that misses while its neighbours in the packet (beside it in its row,
// above or below it) all hit is traced once more turned by 1e-5 rad: Embree's robust mode closes shared
// edges, but a ray exactly through a shared vertex can still slip between the triangles around
// it (hits.retraced counts these). Returns the number of rays cast, retries included.
std::uint64_t traceStraight(RTCScene scene, int count, int columns, PacketHits& hits);

// traceStraight for two packets at once: with one rtcIntersect16 where `native16` (the device traces
// 16-ray packets natively: Embree's 16-wide traversal with AVX-512 is ~20 % faster a ray than
// two 8-wide ones) and both have rays, else with rtcIntersect8 each; the same hits either way.
// The lone-miss retry stays per packet.
std::uint64_t traceStraightPair(RTCScene scene, const std::array<int, 2>& count,
                                const std::array<int, 2>& columns,
                                std::array<PacketHits, 2>& hits, bool native16);

// Traces `count` (<= 8) bent paths: every lane's segments in order until one hits, then the
// lone-miss retry of traceStraight along the tail. Unlit paths are not traced. Returns the
// number of rays cast (one per lane and segment, retries included).
std::uint64_t tracePaths(RTCScene scene, const RayPath* paths, int count, int columns,
                         PacketHits& hits);

struct OcclusionPacket {
  std::array<bool, kPacketSize> active{};
  std::array<glm::vec3, kPacketSize> origin{}, direction{};
  std::array<float, kPacketSize> distance{};
  std::array<bool, kPacketSize> occluded{};
};

// Fills packet.occluded for the active lanes; returns the number of rays cast.
std::uint64_t traceOcclusion(RTCScene scene, OcclusionPacket& packet);

}  // namespace confvis::embree
