// Gaze alignment and mirror symmetry of a baked map (map_alignment_quality.hpp).
#include "confvis/conformal/map_alignment_quality.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "confvis/base/error.hpp"
#include "display_alignment.hpp"

namespace confvis {
namespace {

Vec3d toVec(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

// Where the ray from the reference along `dir` meets the wall's full rectangle (bezels
// included), as distance along the ray; nullopt if it misses.
std::optional<double> hitWall(const Wall& wall, const Vec3d& c, const Vec3d& dir) {
  const Vec3d n = toVec(wall.normal()), ll = toVec(wall.lowerLeft);
  const double along = dot(dir, n);
  if (std::abs(along) < 1e-12) return std::nullopt;
  const double lambda = dot(ll - c, n) / along;
  if (!(lambda > 0)) return std::nullopt;
  const Vec3d q = c + lambda * dir - ll;
  const double s = dot(q, toVec(wall.right())) / wall.widthMetres();
  const double t = dot(q, toVec(wall.up())) / wall.heightMetres();
  if (s < -1e-9 || s > 1 + 1e-9 || t < -1e-9 || t > 1 + 1e-9) return std::nullopt;
  return lambda;
}

double pitch(const Wall& lit) { return lit.widthMetres() / lit.width; }

Vec3d rotateToward(const Vec3d& d, const Vec3d& tangent, double angle) {
  return normalized(std::cos(angle) * d + std::sin(angle) * tangent);
}

double percentile(std::vector<double>& v, double q) {
  if (v.empty()) return 0;
  const std::size_t k = std::min(v.size() - 1, static_cast<std::size_t>(q * v.size()));
  std::nth_element(v.begin(), v.begin() + k, v.end());
  return v[k];
}

}  // namespace

GazeAlignment measureGazeAlignment(const RetargetMap& map, const DisplayConfig& config,
                                   const Vec3d& forward) {
  const Vec3d c = map.reference;
  const Vec3d f = normalized(forward);
  const std::optional<Vec3d> shown = map.toPhysical(f);
  if (!shown)
    throw Error(ErrorCode::InvalidInput,
                config.name + ": the forward direction is outside the map's source field");
  const Wall* best = nullptr;
  double nearest = 1e300;
  for (const Wall& w : config.walls)
    if (const auto lambda = hitWall(w, c, *shown); lambda && *lambda < nearest)
      nearest = *lambda, best = &w;
  if (!best)
    throw Error(ErrorCode::InvalidInput,
                config.name + ": the forward direction's content is shown on no wall");
  const Wall lit = best->litRectangle();
  const Vec3d ll = toVec(lit.lowerLeft);
  const Vec3d q = c + nearest * *shown;
  GazeAlignment out;
  out.wall = best->name;
  out.s = dot(q - ll, toVec(lit.right())) / lit.widthMetres();
  out.t = dot(q - ll, toVec(lit.up())) / lit.heightMetres();
  if (const auto lambda = hitWall(*best, c, f)) {
    const Vec3d ahead = c + *lambda * f;
    out.offsetPixels = norm(q - ahead) / pitch(lit);
    // Up at the straight-ahead point: ray's central difference over a few pixels.
    const double step = std::max(1.0, 0.01 * lit.width) * pitch(lit) / *lambda;
    const Vec3d up = detail::upAt(f);
    const auto above = map.toVirtual(rotateToward(f, up, step));
    const auto below = map.toVirtual(rotateToward(f, up, -step));
    const auto centre = map.toVirtual(f);
    if (above && below && centre) {
      Vec3d image = *above - *below;
      image = image - dot(image, *centre) * *centre;
      out.upTiltDegrees = angleBetween(image, detail::upAt(*centre)) * 180 / std::numbers::pi;
    }
  }
  return out;
}

MirrorAsymmetry measureMirrorAsymmetry(const RetargetMap& map, const DisplayConfig& config,
                                       const Vec3d& planeNormal, int samplesPerSide,
                                       double margin) {
  const Vec3d n = normalized(planeNormal);
  const Vec3d c = map.reference;
  auto mirror = [&](const Vec3d& d) { return d - 2 * dot(d, n) * n; };
  std::vector<double> pixels;
  std::vector<std::string> walls;
  for (const Wall& wall : config.walls) {
    const Wall lit = wall.litRectangle();
    const Vec3d right = toVec(lit.right()), up = toVec(lit.up());
    const double k = std::max(1.0, 0.01 * lit.width) * pitch(lit);
    for (int i = 0; i < samplesPerSide; ++i)
      for (int j = 0; j < samplesPerSide; ++j) {
        const double s = margin + (1 - 2 * margin) * (i + 0.5) / samplesPerSide;
        const double t = margin + (1 - 2 * margin) * (j + 0.5) / samplesPerSide;
        const Vec3d p = toVec(lit.pointAt(s, t));
        const auto v = map.toVirtual(p - c);
        const auto mirrored = map.toVirtual(mirror(p - c));
        const auto r1 = map.toVirtual(p + k * right - c), r0 = map.toVirtual(p - k * right - c);
        const auto u1 = map.toVirtual(p + k * up - c), u0 = map.toVirtual(p - k * up - c);
        if (!v || !mirrored || !r1 || !r0 || !u1 || !u0) continue;
        const double perPixel =
            std::min(angleBetween(*r1, *r0), angleBetween(*u1, *u0)) / (2 * k / pitch(lit));
        if (!(perPixel > 0)) continue;
        pixels.push_back(angleBetween(*mirrored, mirror(*v)) / perPixel);
        walls.push_back(wall.name);
      }
  }
  MirrorAsymmetry out;
  out.samples = pixels.size();
  if (pixels.empty()) return out;
  const auto worst = std::max_element(pixels.begin(), pixels.end());
  out.max = *worst;
  out.worstWall = walls[worst - pixels.begin()];
  out.p50 = percentile(pixels, 0.5);
  out.p99 = percentile(pixels, 0.99);
  return out;
}

}  // namespace confvis
