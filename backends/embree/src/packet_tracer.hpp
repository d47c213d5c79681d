#pragma once
// Tracing in packets of 8 (rtcIntersect8 / rtcOccluded8): primary paths segment by segment, and
// shadow-style occlusion rays for ambient occlusion.
#include <embree3/rtcore.h>

#include <array>
#include <cstdint>

#include <glm/glm.hpp>

#include "camera_rays.hpp"

namespace confvis::embree {

inline constexpr int kPacketSize = 8;

struct PacketHits {
  std::array<bool, kPacketSize> hit{};
  std::array<unsigned, kPacketSize> geomID{}, primID{};
  std::array<glm::vec2, kPacketSize> barycentrics{};
  std::array<glm::vec3, kPacketSize> geometricNormal{}, point{};
  std::array<glm::vec3, kPacketSize> direction{};  // unit direction of the segment that hit
  int retraced = 0;  // lanes traced a second time (see tracePaths)
};

// Traces `count` (<= 8) paths: every lane's segments in order until one hits. Unlit paths are
// not traced. A lane that misses while its packet neighbours (both, or the only one) hit is
// traced once more with its tail turned by 1e-5 rad: Embree's robust mode closes shared edges,
// but a ray exactly through a shared vertex can still slip between the triangles around it
// (hits.retraced counts these). Returns the number of rays cast (one per lane and segment,
// retries included).
std::uint64_t tracePaths(RTCScene scene, const RayPath* paths, int count, PacketHits& hits);

struct OcclusionPacket {
  std::array<bool, kPacketSize> active{};
  std::array<glm::vec3, kPacketSize> origin{}, direction{};
  std::array<float, kPacketSize> distance{};
  std::array<bool, kPacketSize> occluded{};
};

// Fills packet.occluded for the active lanes; returns the number of rays cast.
std::uint64_t traceOcclusion(RTCScene scene, OcclusionPacket& packet);

}  // namespace confvis::embree
