#pragma once
// Helpers shared by the map error measurements (map_accuracy.cpp, map_reference_extrapolation.cpp).
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "confvis/conformal/map_accuracy.hpp"
#include "parallel_for.hpp"

namespace confvis::detail {

template <class Stats>
void fillPercentiles(std::vector<double>& values, Stats& out) {
  out.samples = values.size();
  if (values.empty()) return;
  std::sort(values.begin(), values.end());
  auto at = [&](double q) {
    return values[std::min(values.size() - 1, static_cast<std::size_t>(q * values.size()))];
  };
  out.p50 = at(0.5);
  out.p95 = at(0.95);
  out.p99 = at(0.99);
  out.max = values.back();
}

// A sample point of a wall: the centre of cell (i, j) of an n x n grid over its lit rectangle.
struct WallGridPoint {
  Vec3d p;
  double pitch;  // metres per pixel of the wall
  int wall;
  double s, t;
};

// Calls visit(row, lit, point) for every wall's grid points, a row (wall w, grid row j; row index
// w * n + j) per parallel task, in order within the row.
template <class Visit>
void forEachWallGridPoint(const DisplayConfig& config, int n, int threads, Visit&& visit) {
  parallelFor(config.walls.size() * n, threads, [&](std::size_t row) {
    const int w = static_cast<int>(row / n), j = static_cast<int>(row % n);
    const Wall lit = config.walls[w].litRectangle();
    const double pitch = lit.widthMetres() / lit.width;
    for (int i = 0; i < n; ++i) {
      const double s = (i + 0.5) / n, t = (j + 0.5) / n;
      visit(row, lit, WallGridPoint{lit.pointAt(s, t), pitch, w, s, t});
    }
  });
}

// Where the ray from c along dir meets a wall's full rectangle (bezels included): the nearest
// hit's distance along the ray; nullopt if it meets none.
inline std::optional<Vec3d> hitDisplay(const DisplayConfig& config, const Vec3d& c, const Vec3d& dir) {
  std::optional<Vec3d> best;
  double nearest = 1e300;
  for (const Wall& wall : config.walls) {
    const Vec3d n = wall.normal();
    const double along = dot(dir, n);
    if (std::abs(along) < 1e-12) continue;
    const double lambda = dot(wall.lowerLeft - c, n) / along;
    if (!(lambda > 0) || lambda >= nearest) continue;
    const Vec3d q = c + lambda * dir - wall.lowerLeft;
    const double s = dot(q, wall.right()) / wall.widthMetres();
    const double t = dot(q, wall.up()) / wall.heightMetres();
    const double tol = 1e-6;
    if (s < -tol || s > 1 + tol || t < -tol || t > 1 + tol) continue;
    nearest = lambda;
    best = c + lambda * dir;
  }
  return best;
}

// Where the ray meets the plane of `wall` (content moved past the display's edge is measured in
// the plane of the wall it left).
inline std::optional<Vec3d> hitPlane(const Wall& wall, const Vec3d& c, const Vec3d& dir) {
  const double along = dot(dir, wall.normal());
  if (std::abs(along) < 1e-12) return std::nullopt;
  const double lambda = dot(wall.lowerLeft - c, wall.normal()) / along;
  if (!(lambda > 0)) return std::nullopt;
  return c + lambda * dir;
}

// Where `reference` shows virtual direction v: on the display, else in the plane of `lit`.
inline std::optional<Vec3d> shownAt(const DisplayConfig& config, const DisplayMapEvaluator& reference,
                                    const Wall& lit, const Vec3d& v) {
  const auto back = reference.toPhysical(v);
  if (!back) return std::nullopt;
  std::optional<Vec3d> q = hitDisplay(config, config.reference, back->direction);
  if (!q) q = hitPlane(lit, config.reference, back->direction);
  return q;
}

// One error sample: pixels of its wall, where on the wall's lit rectangle.
struct WallSample {
  double pixels;
  int wall;
  double s, t;
};

inline MapError summarizeWallSamples(const DisplayConfig& config,
                                     const std::vector<std::vector<WallSample>>& rows) {
  std::vector<double> pixels;
  MapError out;
  double worst = -1;
  for (const auto& row : rows)
    for (const WallSample& sample : row) {
      pixels.push_back(sample.pixels);
      if (sample.pixels > worst) {
        worst = sample.pixels;
        out.worstWall = config.walls[sample.wall].name;
        out.worstS = sample.s;
        out.worstT = sample.t;
      }
    }
  fillPercentiles(pixels, out);
  return out;
}

}  // namespace confvis::detail
