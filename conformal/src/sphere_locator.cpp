// Point location on a sphere mesh (sphere_locator.hpp).
#include "sphere_locator.hpp"

#include <algorithm>
#include <cmath>

#include "sphere_raster.hpp"

namespace confvis::detail {
namespace {

// The cell of d on the cube-face grid of n x n cells per face (the EXR layout's texels).
int cellOf(const Vec3d& d, int n, const std::array<CubeFaceFrame, 6>& frames) {
  int face = 0;
  double best = -1e300;
  for (int f = 0; f < 6; ++f)
    if (const double q = dot(d, frames[f].normal); q > best) best = q, face = f;
  const CubeFaceFrame& frame = frames[face];
  auto index = [n](double u) {
    return std::clamp(static_cast<int>(std::floor((u + 1) * 0.5 * n)), 0, n - 1);
  };
  const int x = index(dot(d, frame.right) / best), y = index(dot(d, frame.down) / best);
  return (face * n + y) * n + x;
}

}  // namespace

SphereLocator::SphereLocator(const std::vector<Vec3d>& sphere,
                             const std::vector<std::array<int, 3>>& triangles)
    : sphere_(sphere), triangles_(triangles) {
  edges_.resize(triangles.size());
  sign_.resize(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Vec3d &a = sphere[triangles[t][0]], &b = sphere[triangles[t][1]], &c = sphere[triangles[t][2]];
    edges_[t] = {cross(b, c), cross(c, a), cross(a, b)};
    const double det = dot(a, edges_[t][0]);
    sign_[t] = det > 0 ? 1.0 : det < 0 ? -1.0 : 0.0;
  }
  // About one triangle per cell: the boxes are widened by a cell on each side, so ~9 per cell.
  n_ = std::clamp(static_cast<int>(std::sqrt(triangles.size() / 6.0)), 4, 1024);
  const auto bins = binSphereTriangles(sphere, triangles, n_);
  const int bands = (n_ + kRasterBandRows - 1) / kRasterBandRows;
  const std::size_t cells = 6 * static_cast<std::size_t>(n_) * n_;
  std::vector<int> count(cells + 1, 0);
  auto forEachCell = [&](auto&& visit) {
    for (std::size_t task = 0; task < bins.size(); ++task) {
      const int face = static_cast<int>(task / bands), band = static_cast<int>(task % bands);
      const int y0 = band * kRasterBandRows, y1 = std::min(n_, y0 + kRasterBandRows) - 1;
      for (const RasterBinEntry& e : bins[task])
        for (int y = std::max(e.y0, y0); y <= std::min(e.y1, y1); ++y)
          for (int x = e.x0; x <= e.x1; ++x) visit((face * n_ + y) * n_ + x, e.triangle);
    }
  };
  forEachCell([&](int cell, int) { ++count[cell + 1]; });
  for (std::size_t i = 0; i < cells; ++i) count[i + 1] += count[i];
  cellStart_ = count;
  cellTriangles_.resize(count[cells]);
  forEachCell([&](int cell, int t) { cellTriangles_[count[cell]++] = t; });
}

SphereLocator::Hit SphereLocator::locate(const Vec3d& d) const {
  static const std::array<CubeFaceFrame, 6> frames = [] {
    std::array<CubeFaceFrame, 6> f;
    for (CubeFace face : kCubeFaces) f[static_cast<int>(face)] = cubeFaceFrame(face);
    return f;
  }();
  const int cell = cellOf(d, n_, frames);
  // The triangle d is most inside of (largest smallest barycentric): exact inside where one
  // contains d, the nearest otherwise (d on an edge, rounding).
  Hit best;
  double bestMin = -1e300;
  for (int i = cellStart_[cell]; i < cellStart_[cell + 1]; ++i) {
    const int t = cellTriangles_[i];
    if (sign_[t] == 0) continue;
    std::array<double, 3> w;
    for (int k = 0; k < 3; ++k) w[k] = sign_[t] * dot(d, edges_[t][k]);
    const double sum = w[0] + w[1] + w[2];
    if (!(sum > 0)) continue;  // the chord triangle's plane is behind the centre for d
    const double m = std::min({w[0], w[1], w[2]}) / sum;
    if (m > bestMin) {
      bestMin = m;
      best.triangle = t;
      best.barycentric = {w[0] / sum, w[1] / sum, w[2] / sum};
    }
  }
  if (bestMin < -1e-6) best.triangle = -1;  // no triangle of this cell covers d
  return best;
}

}  // namespace confvis::detail
