#pragma once
// Rasterises a triangle mesh on the unit sphere into the texels of a cube map (EXR layout,
// confvis/base/cube_map.hpp): for every row span of texels covered by a triangle, calls
// shadeSpan(span, state) (RasterSpan below). The triangles are the flat chords between
// their unit-vector corners, so d is inside triangle (a, b, c) exactly when the triple products
// det(d, b, c), det(d, c, a), det(d, a, b) share det(a, b, c)'s sign, and those products,
// normalised, are the barycentric coordinates of the point where the ray along d meets the chord
// triangle: the piecewise-linear map's own coordinates, so coverage and values are exact.
//
// Work is split into (face, band of rows) tasks run in parallel; each texel belongs to one task,
// so shaders write their texels without synchronisation. `state` is a TaskState per task,
// value-initialised, for the shader's point-location walk (consecutive texels of a triangle land
// close together); a triangle's spans come row after row.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <vector>

#include "confvis/base/cube_map.hpp"
#include "confvis/base/vec3.hpp"
#include "parallel_for.hpp"

namespace confvis::detail {

// Texel (x, y) of a face has direction normal + c(x) right + c(y) down, c(i) = (2i + 1 - N) / N.
struct CubeFaceFrame {
  Vec3d normal{0.0}, right{0.0}, down{0.0};
};
CubeFaceFrame cubeFaceFrame(CubeFace face);
inline double texelCoordinate(int i, int n) { return static_cast<double>(2 * i + 1 - n) / n; }

// Texels per task band: enough tasks to balance 2..16 threads, few enough to bin cheaply.
inline constexpr int kRasterBandRows = 16;

// Texels xBegin..xEnd (inclusive) of row y of `face`, all inside `triangle`. The triple
// products (sign-corrected to be >= 0 inside) are w at xBegin and change by step per texel;
// the texel's barycentric coordinates are w / (w0 + w1 + w2).
struct RasterSpan {
  CubeFace face;
  int y, xBegin, xEnd, triangle;
  std::array<double, 3> w, step;
};

struct RasterBinEntry {
  int triangle, x0, x1, y0, y1;  // inclusive texel box on the task's face
};

// For each (face, band) task, the triangles whose projection may touch it, with their boxes.
std::vector<std::vector<RasterBinEntry>> binSphereTriangles(
    const std::vector<Vec3d>& sphere, const std::vector<std::array<int, 3>>& triangles, int n);

// A mesh set up for rasterising: its triangles' edge functions and its (face, band) bins. Made
// once, then its tasks run in any order on any thread (rasterizeSphereMesh runs them all; the
// bake runs two meshes' tasks in one parallel loop, so that neither pass waits for the other).
class SphereRaster {
 public:
  SphereRaster(const std::vector<Vec3d>& sphere, const std::vector<std::array<int, 3>>& triangles,
               int n)
      : n_(n), bands_((n + kRasterBandRows - 1) / kRasterBandRows), edges_(triangles.size()) {
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      const Vec3d& a = sphere[triangles[t][0]];
      const Vec3d& b = sphere[triangles[t][1]];
      const Vec3d& c = sphere[triangles[t][2]];
      edges_[t].e = {cross(b, c), cross(c, a), cross(a, b)};
      const double det = dot(a, edges_[t].e[0]);
      edges_[t].sign = det > 0 ? 1.0 : det < 0 ? -1.0 : 0.0;
    }
    bins_ = binSphereTriangles(sphere, triangles, n);
  }

  std::size_t taskCount() const { return bins_.size(); }

  // Calls shadeSpan(span, state) for every span of task `task`, with a fresh TaskState.
  template <class TaskState, class ShadeSpan>
  void runTask(std::size_t task, ShadeSpan&& shadeSpan) const {
    const int n = n_;
    const CubeFace face = kCubeFaces[task / bands_];
    const int band = static_cast<int>(task % bands_);
    const int bandY0 = band * kRasterBandRows, bandY1 = std::min(n, bandY0 + kRasterBandRows) - 1;
    const CubeFaceFrame frame = cubeFaceFrame(face);
    TaskState state{};
    for (const RasterBinEntry& entry : bins_[task]) {
      const Edges& tri = edges_[entry.triangle];
      if (tri.sign == 0) continue;
      const int yBegin = std::max(entry.y0, bandY0), yEnd = std::min(entry.y1, bandY1);
      RasterSpan span{face, 0, 0, 0, entry.triangle, {}, {}};
      // Each triple product is linear in the texel: w at (entry.x0, y) changes by `step` per
      // texel along x and by `rowStep` per row.
      const Vec3d entryStart = frame.normal + texelCoordinate(yBegin, n) * frame.down +
                               texelCoordinate(entry.x0, n) * frame.right;
      std::array<double, 3> w0, rowStep;
      for (int i = 0; i < 3; ++i) {
        const Vec3d e = tri.sign * tri.e[i];
        span.step[i] = dot(frame.right, e) * (2.0 / n);
        rowStep[i] = dot(frame.down, e) * (2.0 / n);
        w0[i] = dot(entryStart, e);
      }
      const int kMax = entry.x1 - entry.x0;
      for (int y = yBegin; y <= yEnd; ++y) {
        if (y > yBegin)
          for (int i = 0; i < 3; ++i) w0[i] += rowStep[i];
        // The exact test of texel entry.x0 + k (tolerant on the edges, so that a texel on an
        // edge shared by two triangles is found by at least one despite rounding): all three
        // at least -1e-12 of their sum, the sum positive.
        auto inside = [&](int k) {
          const double a = w0[0] + k * span.step[0], b = w0[1] + k * span.step[1],
                       c = w0[2] + k * span.step[2];
          const double sum = a + b + c;
          return std::min(a, std::min(b, c)) >= -1e-12 * sum && sum > 0;
        };
        // The triangle is convex, so its texels in this row are one span: solve each edge's
        // linear inequality for k, then settle the ends with the exact test.
        double lo = 0, hi = kMax;
        for (int i = 0; i < 3; ++i) {
          if (span.step[i] > 0) lo = std::max(lo, -w0[i] / span.step[i]);
          else if (span.step[i] < 0) hi = std::min(hi, -w0[i] / span.step[i]);
          else if (w0[i] < -1e-12 * (std::abs(w0[0]) + std::abs(w0[1]) + std::abs(w0[2])))
            lo = kMax + 2.0;  // parallel to the row and outside it
        }
        if (!(lo <= hi + 1.0)) continue;  // more than a texel away from any texel centre
        // lo >= 0 and hi <= kMax here: truncation is floor for lo; hi + 1 > 0.
        int first = std::min(static_cast<int>(lo), kMax);
        const int lastCandidate = std::min(static_cast<int>(hi + 1.0) + 1, kMax);
        while (first <= lastCandidate && !inside(first)) ++first;
        if (first > lastCandidate) continue;
        while (first > 0 && inside(first - 1)) --first;
        int last = std::max(std::min(static_cast<int>(hi + 1.0), kMax), first);
        while (last > first && !inside(last)) --last;
        while (last < kMax && inside(last + 1)) ++last;
        std::array<double, 3> wFirst;
        for (int i = 0; i < 3; ++i) wFirst[i] = w0[i] + first * span.step[i];
        span.y = y;
        span.xBegin = first + entry.x0;
        span.xEnd = last + entry.x0;
        span.w = wFirst;
        shadeSpan(span, state);
      }
    }
  }

 private:
  struct Edges {
    std::array<Vec3d, 3> e;  // e[i] . d = det(d, corner i+1, corner i+2)
    double sign;             // sign of det(a, b, c); 0 for a degenerate triangle
  };
  int n_, bands_;
  std::vector<Edges> edges_;
  std::vector<std::vector<RasterBinEntry>> bins_;
};

template <class TaskState, class ShadeSpan>
void rasterizeSphereMesh(const std::vector<Vec3d>& sphere,
                         const std::vector<std::array<int, 3>>& triangles, int n, int threads,
                         const std::function<void()>& onTaskDone, ShadeSpan&& shadeSpan) {
  const SphereRaster raster(sphere, triangles, n);
  parallelFor(raster.taskCount(), threads, [&](std::size_t task) {
    raster.runTask<TaskState>(task, shadeSpan);
    if (onTaskDone) onTaskDone();
  });
}

}  // namespace confvis::detail
