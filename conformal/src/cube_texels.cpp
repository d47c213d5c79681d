#include "cube_texels.hpp"

#include <algorithm>
#include <cmath>

#include "confvis/base/vec3.hpp"

namespace confvis::detail {

TexelRef neighbourTexel(CubeFace face, int x, int y, int dx, int dy, int n) {
  const int nx = x + dx, ny = y + dy;
  if (nx >= 0 && nx < n && ny >= 0 && ny < n) return {face, nx, ny};
  CubeFace other;
  double ox, oy;
  directionToTexel(texelDirection(face, nx, ny, n), n, other, ox, oy);
  return {other, std::clamp(static_cast<int>(std::floor(ox)), 0, n - 1),
          std::clamp(static_cast<int>(std::floor(oy)), 0, n - 1)};
}

std::vector<std::uint8_t> distanceToUnmasked(const std::vector<std::uint8_t>& mask, int n,
                                             std::uint8_t cap) {
  std::vector<std::uint8_t> distance(mask.size(), cap);
  std::vector<std::size_t> frontier, next;
  for (std::size_t i = 0; i < mask.size(); ++i)
    if (!mask[i]) {
      distance[i] = 0;
      frontier.push_back(i);
    }
  for (std::uint8_t d = 1; d < cap && !frontier.empty(); ++d) {
    next.clear();
    for (std::size_t i : frontier) {
      const TexelRef t = texelAt(i, n);
      for (const auto& step : kNeighbourSteps) {
        const TexelRef nb = neighbourTexel(t.face, t.x, t.y, step[0], step[1], n);
        const std::size_t j = texelIndex(nb.face, nb.x, nb.y, n);
        if (distance[j] > d) {
          distance[j] = d;
          next.push_back(j);
        }
      }
    }
    frontier.swap(next);
  }
  return distance;
}

namespace {

Vec3d texelValue(const CubeMap& map, const TexelRef& t) {
  const float* p = map.face(t.face).at(t.x, t.y);
  return {p[0], p[1], p[2]};
}

void setTexelDirection(CubeMap& map, const TexelRef& t, const Vec3d& d) {
  float* p = map.face(t.face).at(t.x, t.y);
  p[0] = static_cast<float>(d.x);
  p[1] = static_cast<float>(d.y);
  p[2] = static_cast<float>(d.z);
}

}  // namespace

void extendPastBoundary(CubeMap& map, const std::vector<std::uint8_t>& covered) {
  const int n = map.faceSize;
  if (std::find(covered.begin(), covered.end(), 1) == covered.end()) {  // nothing to extend
    for (std::size_t i = 0; i < covered.size(); ++i) {
      const TexelRef t = texelAt(i, n);
      setTexelDirection(map, t, normalized(texelDirection(t.face, t.x, t.y, n)));
    }
    return;
  }
  // Rings of uncovered texels by graph distance from the covered region. A bilinear footprint
  // reaches at most two rings out from a point inside, so the first rings are extrapolated
  // linearly (2 f(a) - f(b) for an earlier neighbour a and the texel b beyond it in the same
  // face row/column); further rings copy a neighbour: the nearest value.
  constexpr int kExtrapolatedRings = 3;
  constexpr int kUnfilled = -1;
  std::vector<int> ringOf(covered.size(), kUnfilled);
  std::vector<std::size_t> frontier, next;
  for (std::size_t i = 0; i < covered.size(); ++i)
    if (covered[i]) {
      ringOf[i] = 0;
      frontier.push_back(i);
    }
  for (int ring = 1; !frontier.empty(); ++ring) {
    next.clear();
    for (std::size_t i : frontier) {
      const TexelRef t = texelAt(i, n);
      for (const auto& step : kNeighbourSteps) {
        const TexelRef nb = neighbourTexel(t.face, t.x, t.y, step[0], step[1], n);
        const std::size_t j = texelIndex(nb.face, nb.x, nb.y, n);
        if (ringOf[j] != kUnfilled) continue;
        ringOf[j] = ring;
        next.push_back(j);
      }
    }
    // Values of this ring read only earlier rings, so the order within a ring does not matter.
    for (std::size_t i : next) {
      const TexelRef t = texelAt(i, n);
      Vec3d sum{}, first{};
      int count = 0;
      for (const auto& step : kNeighbourSteps) {
        const TexelRef a = neighbourTexel(t.face, t.x, t.y, step[0], step[1], n);
        const int ringA = ringOf[texelIndex(a.face, a.x, a.y, n)];
        if (ringA == kUnfilled || ringA >= ring) continue;
        const Vec3d fa = texelValue(map, a);
        Vec3d value = fa;
        if (ring <= kExtrapolatedRings) {
          // b continues the line t -> a on the sphere (across a face edge if need be); the
          // texel spacing differs between faces, so extrapolate by the ratio of the distances.
          const Vec3d dt = normalized(texelDirection(t.face, t.x, t.y, n));
          const Vec3d da = normalized(texelDirection(a.face, a.x, a.y, n));
          CubeFace bFace;
          double bx, by;
          directionToTexel(2.0 * da - dt, n, bFace, bx, by);
          const TexelRef b{bFace, std::clamp(static_cast<int>(bx), 0, n - 1),
                           std::clamp(static_cast<int>(by), 0, n - 1)};
          const int ringB = ringOf[texelIndex(b.face, b.x, b.y, n)];
          const Vec3d db = normalized(texelDirection(b.face, b.x, b.y, n));
          const double spacing = norm(da - db);
          if (ringB != kUnfilled && ringB < ring && spacing > 0.5 * norm(dt - da)) {
            const Vec3d extrapolated = fa + (norm(dt - da) / spacing) * (fa - texelValue(map, b));
            if (norm(extrapolated) > 0.5) value = normalized(extrapolated);
          }
        }
        sum = sum + value;
        if (count++ == 0) first = value;
        if (ring > kExtrapolatedRings) break;  // the nearest value: one neighbour is enough
      }
      // Opposite neighbours across a one-texel gap can cancel: keep the first value then.
      setTexelDirection(map, t, norm(sum) > 1e-6 ? normalized(sum) : first);
    }
    frontier.swap(next);
  }
}

}  // namespace confvis::detail
