#include "sphere_raster.hpp"

namespace confvis::detail {

CubeFaceFrame cubeFaceFrame(CubeFace face) {
  // From the public texel directions of a 2x2 face, c(0) = -1/2 and c(1) = 1/2.
  const Vec3d d00 = texelDirection(face, 0, 0, 2), d11 = texelDirection(face, 1, 1, 2);
  return {0.5 * (d00 + d11), texelDirection(face, 1, 0, 2) - d00, texelDirection(face, 0, 1, 2) - d00};
}

std::vector<std::vector<RasterBinEntry>> binSphereTriangles(
    const std::vector<Vec3d>& sphere, const std::vector<std::array<int, 3>>& triangles, int n) {
  const int bands = (n + kRasterBandRows - 1) / kRasterBandRows;
  std::vector<std::vector<RasterBinEntry>> bins(6 * static_cast<std::size_t>(bands));
  for (CubeFace face : kCubeFaces) {
    const CubeFaceFrame frame = cubeFaceFrame(face);
    const int f = static_cast<int>(face);
    for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
      int behind = 0, inFront = 0;
      double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
      for (int v : triangles[t]) {
        const Vec3d& p = sphere[v];
        const double q = dot(p, frame.normal);
        if (q <= 1e-9) {
          ++behind;
          continue;
        }
        ++inFront;
        const double u = dot(p, frame.right) / q, w = dot(p, frame.down) / q;
        u0 = std::min(u0, u);
        u1 = std::max(u1, u);
        v0 = std::min(v0, w);
        v1 = std::max(v1, w);
      }
      if (inFront == 0) continue;  // the whole triangle is in the half-space behind the face
      // Texel i's centre is at c(i), so c = u gives i = (u N + N - 1) / 2; widen by a texel.
      auto index = [n](double u) { return (u * n + n - 1) * 0.5; };
      int x0 = 0, x1 = n - 1, y0 = 0, y1 = n - 1;
      if (behind == 0) {  // the chord triangle projects to a straight triangle: use its box
        if (index(u1) < -1 || index(u0) > n || index(v1) < -1 || index(v0) > n) continue;
        x0 = std::max(0, static_cast<int>(std::floor(index(u0))) - 1);
        x1 = std::min(n - 1, static_cast<int>(std::ceil(index(u1))) + 1);
        y0 = std::max(0, static_cast<int>(std::floor(index(v0))) - 1);
        y1 = std::min(n - 1, static_cast<int>(std::ceil(index(v1))) + 1);
      }  // else: a triangle wider than 35 degrees straddling the face's horizon: test the face
      for (int band = y0 / kRasterBandRows; band <= y1 / kRasterBandRows; ++band)
        bins[static_cast<std::size_t>(f) * bands + band].push_back({t, x0, x1, y0, y1});
    }
  }
  return bins;
}

}  // namespace confvis::detail
