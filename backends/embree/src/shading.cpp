#include "shading.hpp"

#include <cmath>

#include <glm/gtc/constants.hpp>

#include "sampling.hpp"

namespace confvis::embree {

namespace {

// Cosine-weighted direction around unit n (Malley's method with a branch-free orthonormal
// basis, Duff et al. 2017).
glm::vec3 cosineSample(const glm::vec3& n, float u1, float u2) {
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z);
  const float b = n.x * n.y * a;
  const glm::vec3 t(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
  const glm::vec3 s(b, sign + n.y * n.y * a, -n.y);
  const float r = std::sqrt(u1), phi = glm::two_pi<float>() * u2;
  return r * std::cos(phi) * t + r * std::sin(phi) * s + std::sqrt(std::max(0.0f, 1.0f - u1)) * n;
}

}  // namespace

std::uint64_t shadePacket(const EmbreeScene& scene, const PacketHits& hits,
                          const ShadingOptions& options,
                          const std::array<std::uint32_t, kPacketSize>& seeds,
                          PacketColours& colours) {
  // The surface per lane lit by the headlight (surface_shading.cpp), then ambient occlusion.
  SurfaceNormals surface;
  shadeSurface(options.simd, scene, hits, options.pointHeadlight ? &options.headlight : nullptr,
               colours, surface);
  const auto &nx = surface.nx, &ny = surface.ny, &nz = surface.nz;
  const auto& towardsViewer = surface.towardsViewer;
  if (!options.ambientOcclusion || options.occlusionSamples <= 0) return 0;

  std::array<glm::vec3, kPacketSize> normals{};  // unit, towards the viewer
  for (int lane = 0; lane < kPacketSize; ++lane)
    normals[lane] = towardsViewer[lane] * glm::vec3(nx[lane], ny[lane], nz[lane]);
  std::array<glm::vec3, kPacketSize> points{};
  for (int lane = 0; lane < kPacketSize; ++lane)
    if (hits.hit[lane]) points[lane] = hits.point(lane);
  std::uint64_t rays = 0;
  std::array<int, kPacketSize> open{};
  std::array<Random, kPacketSize> rngs;
  for (int lane = 0; lane < kPacketSize; ++lane) rngs[lane] = Random(seeds[lane], 0xa0u, 7u);
  const int n = options.occlusionSamples;
  for (int k = 0; k < n; ++k) {
    OcclusionPacket packet;
    for (int lane = 0; lane < kPacketSize; ++lane) {
      packet.active[lane] = hits.hit[lane];
      if (!hits.hit[lane]) continue;
      // Stratified in the first dimension (k), random in the second.
      const float u1 = (static_cast<float>(k) + rngs[lane].next()) / static_cast<float>(n);
      const float u2 = rngs[lane].next();
      packet.direction[lane] = cosineSample(normals[lane], u1, u2);
      packet.origin[lane] = points[lane] + options.surfaceOffset * normals[lane];
      packet.distance[lane] = options.occlusionDistance;
    }
    rays += traceOcclusion(scene.handle(), packet);
    for (int lane = 0; lane < kPacketSize; ++lane)
      if (packet.active[lane] && !packet.occluded[lane]) ++open[lane];
  }
  for (int lane = 0; lane < kPacketSize; ++lane)
    if (hits.hit[lane]) {
      const float visible = static_cast<float>(open[lane]) / static_cast<float>(n);
      colours.red[lane] *= visible, colours.green[lane] *= visible, colours.blue[lane] *= visible;
    }
  return rays;
}

}  // namespace confvis::embree

namespace confvis::embree {

SimdLevel detectedSimdLevel() {
#if defined(CONFVIS_EMBREE_AVX2)
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) return SimdLevel::Avx2;
#endif
  return SimdLevel::Sse2;
}

const char* simdName(SimdLevel level) { return level == SimdLevel::Avx2 ? "avx2" : "sse2"; }

}  // namespace confvis::embree
