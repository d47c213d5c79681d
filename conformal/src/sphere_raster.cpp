#include "sphere_raster.hpp"

namespace confvis::detail {

CubeFaceFrame cubeFaceFrame(CubeFace face) {
  // From the public texel directions of a 2x2 face, c(0) = -1/2 and c(1) = 1/2.
  const Vec3d d00 = texelDirection(face, 0, 0, 2), d11 = texelDirection(face, 1, 1, 2);
  return {0.5 * (d00 + d11), texelDirection(face, 1, 0, 2) - d00, texelDirection(face, 0, 1, 2) - d00};
}

namespace {

// Clips a convex polygon to the half-space dot(p, normal) >= 0 (Sutherland-Hodgman).
void clip(std::vector<Vec3d>& polygon, const Vec3d& normal, std::vector<Vec3d>& scratch) {
  scratch.clear();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec3d& a = polygon[i];
    const Vec3d& b = polygon[(i + 1) % polygon.size()];
    const double da = dot(a, normal), db = dot(b, normal);
    if (da >= 0) scratch.push_back(a);
    if ((da >= 0) != (db >= 0)) scratch.push_back(a + (da / (da - db)) * (b - a));
  }
  polygon.swap(scratch);
}

}  // namespace

std::vector<std::vector<RasterBinEntry>> binSphereTriangles(
    const std::vector<Vec3d>& sphere, const std::vector<std::array<int, 3>>& triangles, int n) {
  const int bands = (n + kRasterBandRows - 1) / kRasterBandRows;
  std::vector<std::vector<RasterBinEntry>> bins(6 * static_cast<std::size_t>(bands));
  // The face's directions form the pyramid dot(p, normal) >= |dot(p, right)|, |dot(p, down)|:
  // four half-spaces. The cone over a chord triangle meets the face where the triangle,
  // clipped to them, is non-empty, and projects into the box of the clipped polygon.
  std::array<CubeFaceFrame, 6> frames;
  std::array<std::array<Vec3d, 4>, 6> sides;
  for (CubeFace face : kCubeFaces) {
    const int f = static_cast<int>(face);
    const CubeFaceFrame& frame = frames[f] = cubeFaceFrame(face);
    sides[f] = {frame.normal + frame.right, frame.normal - frame.right, frame.normal + frame.down,
                frame.normal - frame.down};
  }
  std::vector<Vec3d> polygon, scratch;
  auto addEntry = [&](int f, int t) {
    const CubeFaceFrame& frame = frames[f];
    double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
    bool degenerate = false;
    for (const Vec3d& p : polygon) {
      const double q = dot(p, frame.normal);
      if (q <= 1e-12) {  // only the origin itself: a chord triangle through the centre
        degenerate = true;
        break;
      }
      const double u = dot(p, frame.right) / q, w = dot(p, frame.down) / q;
      u0 = std::min(u0, u);
      u1 = std::max(u1, u);
      v0 = std::min(v0, w);
      v1 = std::max(v1, w);
    }
    // Texel i's centre is at c(i), so c = u gives i = (u N + N - 1) / 2; widen by a texel
    // for rounding (the inside test decides).
    auto index = [n](double u) { return (u * n + n - 1) * 0.5; };
    int x0 = 0, x1 = n - 1, y0 = 0, y1 = n - 1;
    if (!degenerate) {
      x0 = std::max(0, static_cast<int>(std::floor(index(u0))) - 1);
      x1 = std::min(n - 1, static_cast<int>(std::ceil(index(u1))) + 1);
      y0 = std::max(0, static_cast<int>(std::floor(index(v0))) - 1);
      y1 = std::min(n - 1, static_cast<int>(std::ceil(index(v1))) + 1);
    }
    for (int band = y0 / kRasterBandRows; band <= y1 / kRasterBandRows; ++band)
      bins[static_cast<std::size_t>(f) * bands + band].push_back({t, x0, x1, y0, y1});
  };
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t) {
    const std::array<Vec3d, 3> corners = {sphere[triangles[t][0]], sphere[triangles[t][1]],
                                          sphere[triangles[t][2]]};
    polygon.assign(corners.begin(), corners.end());
    // Most triangles lie strictly inside one face's pyramid (that of their first corner's
    // largest coordinate): every other face has a side plane with all three corners outside,
    // so the general test below would skip it. Only this face then, unclipped.
    const Vec3d& a = corners[0];
    const double ax = std::abs(a.x), ay = std::abs(a.y), az = std::abs(a.z);
    const int home = ax >= ay && ax >= az ? (a.x >= 0 ? 0 : 1)
                     : ay >= az           ? (a.y >= 0 ? 2 : 3)
                                          : (a.z >= 0 ? 4 : 5);
    bool inHome = true;
    for (const Vec3d& side : sides[home])
      for (const Vec3d& p : corners) inHome &= dot(p, side) > 0;
    if (inHome) {
      addEntry(home, t);
      continue;
    }
    for (int f = 0; f < 6; ++f) {
      // Most triangles lie wholly inside or wholly outside one side plane: clip only the rest.
      bool outside = false, straddles = false;
      for (const Vec3d& side : sides[f]) {
        int in = 0;
        for (const Vec3d& p : corners) in += dot(p, side) >= 0;
        outside |= in == 0;
        straddles |= in > 0 && in < 3;
      }
      if (outside) continue;
      polygon.assign(corners.begin(), corners.end());
      if (straddles)
        for (const Vec3d& side : sides[f]) {
          clip(polygon, side, scratch);
          if (polygon.empty()) break;
        }
      if (!polygon.empty()) addEntry(f, t);
    }
  }
  return bins;
}

}  // namespace confvis::detail
