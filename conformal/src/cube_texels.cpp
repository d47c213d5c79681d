#include "cube_texels.hpp"

#include <algorithm>
#include <cmath>

#include "confvis/base/vec3.hpp"

namespace confvis::detail {

TexelRef texelAcrossEdge(CubeFace face, int nx, int ny, int n) {
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
    for (CubeFace face : kCubeFaces)
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
          setTexelDirection(map, {face, x, y}, normalized(texelDirection(face, x, y, n)));
    return;
  }
  // Rings of uncovered texels by graph distance from the covered region. A bilinear footprint
  // reaches at most two rings out from a point inside, so the first rings are extrapolated
  // linearly from an earlier neighbour a and the texel b beyond it; further rings copy a
  // neighbour: the nearest value.
  constexpr int kExtrapolatedRings = 3;
  constexpr std::uint16_t kUnfilled = 0xffff;  // rings stay below 3 N <= 24576
  std::vector<std::uint16_t> ringOf(covered.size(), kUnfilled);
  auto ringAt = [&](const TexelRef& t) -> std::uint16_t& { return ringOf[texelIndex(t.face, t.x, t.y, n)]; };
  std::vector<TexelRef> frontier, next;
  for (std::size_t i = 0; i < covered.size(); ++i)
    if (covered[i]) ringOf[i] = 0;
  // Ring 1: uncovered texels next to a covered one (face by face, row by row). Inside a face
  // the neighbours are the texels beside, above and below; only texels on the face's rim need
  // the step across the edge.
  for (CubeFace face : kCubeFaces)
    for (int y = 0; y < n; ++y) {
      const std::size_t row = texelIndex(face, 0, y, n);
      const bool rimRow = y == 0 || y == n - 1;
      for (int x = 0; x < n; ++x) {
        const std::size_t i = row + x;
        if (ringOf[i] == 0) continue;
        bool nextToCovered = false;
        if (!rimRow && x > 0 && x < n - 1) {
          nextToCovered = ringOf[i - 1] == 0 || ringOf[i + 1] == 0 || ringOf[i - n] == 0 ||
                          ringOf[i + n] == 0;
        } else {
          for (const auto& step : kNeighbourSteps)
            nextToCovered |= ringAt(neighbourTexel(face, x, y, step[0], step[1], n)) == 0;
        }
        if (nextToCovered) frontier.push_back({face, x, y});
      }
    }
  for (const TexelRef& t : frontier) ringAt(t) = 1;

  // The extrapolated rings: each value reads only earlier rings, so order within a ring does
  // not matter.
  int ring = 1;
  for (; ring <= kExtrapolatedRings && !frontier.empty(); ++ring) {
    for (const TexelRef& t : frontier) {
      Vec3d sum{}, first{};
      int count = 0;
      const Vec3d dt = normalized(texelDirection(t.face, t.x, t.y, n));
      for (const auto& step : kNeighbourSteps) {
        const TexelRef a = neighbourTexel(t.face, t.x, t.y, step[0], step[1], n);
        if (ringAt(a) >= ring) continue;  // unfilled, or this ring
        const Vec3d fa = texelValue(map, a);
        Vec3d value = fa;
        // b continues the line t -> a on the sphere (across a face edge if need be); the
        // texel spacing differs between faces, so extrapolate by the ratio of the distances.
        const Vec3d da = normalized(texelDirection(a.face, a.x, a.y, n));
        CubeFace bFace;
        double bx, by;
        directionToTexel(2.0 * da - dt, n, bFace, bx, by);
        const TexelRef b{bFace, std::clamp(static_cast<int>(bx), 0, n - 1),
                         std::clamp(static_cast<int>(by), 0, n - 1)};
        const Vec3d db = normalized(texelDirection(b.face, b.x, b.y, n));
        const double spacing = norm(da - db);
        if (ringAt(b) < ring && spacing > 0.5 * norm(dt - da)) {
          const Vec3d extrapolated = fa + (norm(dt - da) / spacing) * (fa - texelValue(map, b));
          if (norm(extrapolated) > 0.5) value = normalized(extrapolated);
        }
        sum = sum + value;
        if (count++ == 0) first = value;
      }
      // Opposite neighbours across a one-texel gap can cancel: keep the first value then.
      setTexelDirection(map, t, count > 1 && norm(sum) > 1e-6 ? normalized(sum) : first);
    }
    next.clear();
    for (const TexelRef& t : frontier)
      for (const auto& step : kNeighbourSteps) {
        const TexelRef nb = neighbourTexel(t.face, t.x, t.y, step[0], step[1], n);
        std::uint16_t& r = ringAt(nb);
        if (r != kUnfilled) continue;
        r = static_cast<std::uint16_t>(ring + 1);
        // The nearest value for now; the next extrapolated ring overwrites it.
        std::copy_n(map.face(t.face).at(t.x, t.y), 3, map.face(nb.face).at(nb.x, nb.y));
        next.push_back(nb);
      }
    frontier.swap(next);
  }
  // Further out, breadth first: each texel copies the texel that reached it, the nearest value.
  for (; !frontier.empty(); ++ring) {
    next.clear();
    for (const TexelRef& t : frontier) {
      const float* value = map.face(t.face).at(t.x, t.y);
      for (const auto& step : kNeighbourSteps) {
        const TexelRef nb = neighbourTexel(t.face, t.x, t.y, step[0], step[1], n);
        std::uint16_t& r = ringAt(nb);
        if (r != kUnfilled) continue;
        r = static_cast<std::uint16_t>(std::min(ring + 1, 0xfffe));
        std::copy_n(value, 3, map.face(nb.face).at(nb.x, nb.y));
        next.push_back(nb);
      }
    }
    frontier.swap(next);
  }
}

}  // namespace confvis::detail
