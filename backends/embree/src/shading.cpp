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
                          std::array<glm::vec3, kPacketSize>& colours) {
  std::array<glm::vec3, kPacketSize> normals{};
  for (int lane = 0; lane < kPacketSize; ++lane) {
    colours[lane] = glm::vec3(0.0f);
    if (!hits.hit[lane]) continue;
    glm::vec3 n = scene.shadingNormal(hits.geomID[lane], hits.primID[lane],
                                      hits.barycentrics[lane].x, hits.barycentrics[lane].y,
                                      hits.geometricNormal[lane]);
    // Two-sided: turn the normal towards the viewer, so files with either winding shade alike.
    if (glm::dot(n, hits.direction[lane]) > 0.0f) n = -n;
    normals[lane] = n;
    const glm::vec4 base = scene.baseColor(hits.geomID[lane], hits.primID[lane],
                                           hits.barycentrics[lane].x, hits.barycentrics[lane].y);
    colours[lane] = glm::vec3(base) * std::max(0.0f, -glm::dot(n, hits.direction[lane]));
  }
  if (!options.ambientOcclusion || options.occlusionSamples <= 0) return 0;

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
      packet.origin[lane] = hits.point[lane] + options.surfaceOffset * normals[lane];
      packet.distance[lane] = options.occlusionDistance;
    }
    rays += traceOcclusion(scene.handle(), packet);
    for (int lane = 0; lane < kPacketSize; ++lane)
      if (packet.active[lane] && !packet.occluded[lane]) ++open[lane];
  }
  for (int lane = 0; lane < kPacketSize; ++lane)
    if (hits.hit[lane]) colours[lane] *= static_cast<float>(open[lane]) / static_cast<float>(n);
  return rays;
}

}  // namespace confvis::embree
