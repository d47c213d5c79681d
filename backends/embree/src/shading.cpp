#include "shading.hpp"

#include <cmath>

#include <glm/gtc/constants.hpp>

#include "sampling.hpp"
#include "surface_packet.hpp"

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
  // The surface per lane (gathers, then vectorised arithmetic), then the headlight over all 8
  // lanes without branches; lanes without a hit carry zeros through and come out black.
  const RTCRayHit8& r = hits.rayhit;
  SurfacePacket surface;
  surfaceAt(scene, hits, surface);
  const auto &nx = surface.nx, &ny = surface.ny, &nz = surface.nz;
  alignas(32) std::array<float, kPacketSize> towardsViewer;  // -1 or 1 / |n|, see below
  for (int lane = 0; lane < kPacketSize; ++lane) {
    const float dx = r.ray.dir_x[lane], dy = r.ray.dir_y[lane], dz = r.ray.dir_z[lane];
    const float lengthSquared = nx[lane] * nx[lane] + ny[lane] * ny[lane] + nz[lane] * nz[lane];
    const float facing = nx[lane] * dx + ny[lane] * dy + nz[lane] * dz;
    // 1 / |n|, 0 for a zero normal (a missed lane); computed unconditionally so that the loop
    // vectorises (the compiler may not speculate a division by zero).
    const bool nonzero = lengthSquared > 0.0f;
    const float root = std::sqrt(nonzero ? lengthSquared : 1.0f);
    const float inverse = 1.0f / root;
    const float inverseLength = nonzero ? inverse : 0.0f;
    // Two-sided: the normal turned towards the viewer, so files with either winding shade alike;
    // Lambert with the headlight is then |n . d| / |n|.
    towardsViewer[lane] = facing > 0.0f ? -inverseLength : inverseLength;
    const float lambert = std::abs(facing) * inverseLength;
    colours.red[lane] = surface.red[lane] * lambert;
    colours.green[lane] = surface.green[lane] * lambert;
    colours.blue[lane] = surface.blue[lane] * lambert;
  }
  // Apart: reading the bool array in the loop above keeps GCC from vectorising it.
  for (int lane = 0; lane < kPacketSize; ++lane) colours.alpha[lane] = hits.hit[lane] ? 1.0f : 0.0f;
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
