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
  // Structure of arrays: the gathers (normals, texels) per lane first, then the arithmetic
  // (normalisation, headlight Lambert) over all 8 lanes without branches, which the compiler
  // turns into vector sqrt and divide instead of one dependent chain per lane. Missed lanes
  // carry zeros through and come out black.
  alignas(32) std::array<float, kPacketSize> nx{}, ny{}, nz{}, dx{}, dy{}, dz{};
  alignas(32) std::array<float, kPacketSize> red{}, green{}, blue{};
  for (int lane = 0; lane < kPacketSize; ++lane) {
    if (!hits.hit[lane]) continue;
    const float u = hits.barycentrics[lane].x, v = hits.barycentrics[lane].y;
    glm::vec3 n = scene.interpolatedNormal(hits.geomID[lane], hits.primID[lane], u, v);
    if (!(glm::dot(n, n) > 1e-40f)) n = hits.geometricNormal[lane];  // none, or degenerate
    nx[lane] = n.x, ny[lane] = n.y, nz[lane] = n.z;
    const glm::vec3& d = hits.direction[lane];
    dx[lane] = d.x, dy[lane] = d.y, dz[lane] = d.z;
    const glm::vec4 base = scene.baseColor(hits.geomID[lane], hits.primID[lane], u, v);
    red[lane] = base.r, green[lane] = base.g, blue[lane] = base.b;
  }
  alignas(32) std::array<float, kPacketSize> towardsViewer{};  // -1 or 1 / |n|, see below
  for (int lane = 0; lane < kPacketSize; ++lane) {
    const float lengthSquared = nx[lane] * nx[lane] + ny[lane] * ny[lane] + nz[lane] * nz[lane];
    const float facing = nx[lane] * dx[lane] + ny[lane] * dy[lane] + nz[lane] * dz[lane];
    const float inverseLength = lengthSquared > 0.0f ? 1.0f / std::sqrt(lengthSquared) : 0.0f;
    // Two-sided: the normal turned towards the viewer, so files with either winding shade alike;
    // Lambert with the headlight is then |n . d| / |n|.
    towardsViewer[lane] = facing > 0.0f ? -inverseLength : inverseLength;
    const float lambert = std::abs(facing) * inverseLength;
    colours[lane] = glm::vec3(red[lane] * lambert, green[lane] * lambert, blue[lane] * lambert);
  }
  if (!options.ambientOcclusion || options.occlusionSamples <= 0) return 0;

  std::array<glm::vec3, kPacketSize> normals{};  // unit, towards the viewer
  for (int lane = 0; lane < kPacketSize; ++lane)
    normals[lane] = towardsViewer[lane] * glm::vec3(nx[lane], ny[lane], nz[lane]);
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
