// The bake's direction maps through the Möbius blends (smooth_interpolation.hpp). Unlike the
// linear bake (bake.cpp), the disk point is not linear along a span, so every texel is carried
// through both blends and located in the codomain disk by a walk from the texel before.
#include <functional>

#include "cube_texels.hpp"
#include "disk_locator.hpp"
#include "smooth_interpolation.hpp"
#include "sphere_raster.hpp"

namespace confvis::detail {

void bakeDirectionMapSmooth(const SphereDiskMesh& domain, const SphereDiskMesh& codomain,
                            const MobiusBlend& domainBlend, const MobiusBlend& codomainBlend,
                            const DiskLocator& codomainDisk, int threads, CubeMap& out,
                            std::vector<std::uint8_t>& covered, Progress* progress) {
  const int n = out.faceSize;
  covered.assign(6 * static_cast<std::size_t>(n) * n, 0);
  const std::function<void()> onTaskDone = [progress] {
    if (progress) progress->advance();
  };
  struct State {
    int hint = -1;
  };
  auto shadeSpan = [&](const RasterSpan& span, State& state) {
    const auto& tri = domain.triangles[span.triangle];
    const Vec3d& s0 = domain.sphere[tri[0]];
    const Vec3d& s1 = domain.sphere[tri[1]];
    const Vec3d& s2 = domain.sphere[tri[2]];
    const float alpha = domain.lit.empty() || domain.lit[span.triangle] ? 1.0f : 0.0f;
    float* const texels = out.face(span.face).at(span.xBegin, span.y);
    const int count = span.xEnd - span.xBegin + 1;
    for (int k = 0; k < count; ++k) {
      std::array<double, 3> b;
      for (int i = 0; i < 3; ++i) b[i] = span.w[i] + k * span.step[i];
      const double sum = b[0] + b[1] + b[2];
      for (double& x : b) x /= sum;
      // The texel's direction: the ray through the chord point with coordinates b.
      const Vec3d x = normalized(b[0] * s0 + b[1] * s1 + b[2] * s2);
      const std::complex<double> z = domainBlend.toDisk(span.triangle, b, x);
      // Outside the codomain's polygon (the smooth image of a boundary edge bulges towards the
      // unit circle) the nearest boundary triangle's blend is evaluated at z itself: its Möbius
      // maps extend the map smoothly; clamping z would fold the band onto the polygon.
      const DiskLocator::Hit hit = codomainDisk.locate(z, state.hint);
      const auto& image = codomain.triangles[hit.triangle];
      writeDirection(texels + 4 * k, codomainBlend.toSphere(hit.triangle, hit.barycentric, z),
                     codomain.sphere[image[0]], alpha);
    }
    std::fill_n(&covered[texelIndex(span.face, span.xBegin, span.y, n)], count, 1);
  };
  rasterizeSphereMesh<State>(domain.sphere, domain.triangles, n, threads, onTaskDone, shadeSpan);
}

}  // namespace confvis::detail
