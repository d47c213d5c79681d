#pragma once
// The surface under each lane of a traced packet, lit by the headlight: the kernel of a
// shaded camera sample, compiled twice, once for baseline x86-64 (SSE2) and once with AVX2
// (CMakeLists.txt); the backend picks one at startup (simdLevel()). Both compute the same
// floats in the same order (no contraction into FMA), so they render identical pixels.
#include <array>

#include "confvis/backends/embree/embree_scene.hpp"
#include "packet_tracer.hpp"

namespace confvis::embree {

using Lanes = std::array<float, kPacketSize>;

// Linear RGB per lane (base colour x two-sided Lambert with a headlight), and alpha 1 where the
// lane hit something; all zero where it did not.
struct PacketColours {
  alignas(32) Lanes red{}, green{}, blue{}, alpha{};
};

// Per lane, the shading normal (vertex normals interpolated, or the geometric normal where the
// mesh has none or they cancel; not normalised) and the factor that turns it into the unit
// normal facing the viewer (-1 / |n| or 1 / |n|; 0 without a hit).
struct SurfaceNormals {
  alignas(32) Lanes nx, ny, nz, towardsViewer;
};

enum class SimdLevel { Sse2, Avx2 };

// Avx2 where the CPU (and OS) support AVX2 and FMA and this build has the AVX2 variant.
SimdLevel detectedSimdLevel();
const char* simdName(SimdLevel level);

// The tracers' lanes without a hit must carry zero barycentrics, normal and direction (they do).
// The headlight: a point light at `*pointLight` (world), or, with nullptr, light along each ray
// (the same for rays that start at the light; bent rays' last segments do not, which is why
// conformal frames pass the eye's headlightPosition, as the Vulkan backend lights them).
namespace sse2 {
void shadeSurface(const EmbreeScene& scene, const PacketHits& hits, const glm::vec3* pointLight,
                  PacketColours& colours, SurfaceNormals& normals);
}
namespace avx2 {
void shadeSurface(const EmbreeScene& scene, const PacketHits& hits, const glm::vec3* pointLight,
                  PacketColours& colours, SurfaceNormals& normals);
}

inline void shadeSurface(SimdLevel level, const EmbreeScene& scene, const PacketHits& hits,
                         const glm::vec3* pointLight, PacketColours& colours,
                         SurfaceNormals& normals) {
#ifdef CONFVIS_EMBREE_AVX2
  if (level == SimdLevel::Avx2)
    return avx2::shadeSurface(scene, hits, pointLight, colours, normals);
#endif
  (void)level;
  sse2::shadeSurface(scene, hits, pointLight, colours, normals);
}

}  // namespace confvis::embree
