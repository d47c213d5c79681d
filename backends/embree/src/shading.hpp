#pragma once
// Shading of a packet of hits: base colour (material factor x texture, Scene::baseColorAt)
// times Lambert with a headlight (light from the eye along the ray, two-sided), optionally times
// ambient occlusion (the unoccluded fraction of cosine-weighted hemisphere rays).
#include <array>
#include <cstdint>

#include <glm/glm.hpp>

#include "confvis/backends/embree/embree_scene.hpp"
#include "packet_tracer.hpp"
#include "surface_shading.hpp"

namespace confvis::embree {

struct ShadingOptions {
  bool ambientOcclusion = false;
  int occlusionSamples = 8;
  float occlusionDistance = 1.0f;  // metres
  float surfaceOffset = 1e-4f;     // metres, start of occlusion rays above the surface
  SimdLevel simd = SimdLevel::Sse2;  // which variant of the surface kernel runs
  // The headlight: a point light at `headlight` (world) where set, else light along each ray
  // (surface_shading.hpp).
  bool pointHeadlight = false;
  glm::vec3 headlight{0.0f};
};

// Returns the number of occlusion rays cast. `seeds` gives each lane its random stream. Lanes
// without a hit must carry zero barycentrics, normal and direction (as the tracers leave them).
std::uint64_t shadePacket(const EmbreeScene& scene, const PacketHits& hits,
                          const ShadingOptions& options,
                          const std::array<std::uint32_t, kPacketSize>& seeds,
                          PacketColours& colours);

}  // namespace confvis::embree
