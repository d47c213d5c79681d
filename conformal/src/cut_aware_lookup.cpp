#include "cut_aware_lookup.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace confvis::detail {

namespace {

struct Texel4 {
  std::array<double, 4> v{};
  Vec3d direction() const { return {v[0], v[1], v[2]}; }
};

Texel4 scaled(const Texel4& a, double s) {
  Texel4 r;
  for (int c = 0; c < 4; ++c) r.v[c] = s * a.v[c];
  return r;
}

Texel4 combine(const Texel4& a, double wa, const Texel4& b, double wb) {
  Texel4 r;
  for (int c = 0; c < 4; ++c) r.v[c] = wa * a.v[c] + wb * b.v[c];
  return r;
}

// Texel (x, y) of `face`, or its stand-in one texel beyond the face; nullopt further out.
std::optional<Texel4> texelValue(const CubeMap& map, CubeFace face, int x, int y) {
  const int n = map.faceSize;
  if (x < -1 || x > n || y < -1 || y > n) return std::nullopt;
  const TexelStandIn standIn = texelAcrossFaceEdge(face, x, y, n);
  Texel4 value;
  for (int k = 0; k < standIn.count; ++k) {
    const WeightedTexel& r = standIn.texels[k];
    const float* t = map.face(r.texel.face).at(r.texel.x, r.texel.y);
    for (int c = 0; c < 4; ++c) value.v[c] += r.weight * t[c];
  }
  return value;
}

}  // namespace

std::optional<OneSidedSample> sampleOneSide(const CubeMap& map, const Vec3d& dir, int side,
                                            double jumpChord) {
  const int n = map.faceSize;
  CubeFace face;
  double x, y;
  directionToTexel(dir, n, face, x, y);
  // As sampleBilinear: texel centres at i + 0.5, the footprint is the 2x2 block around them.
  const double fx = x - 0.5, fy = y - 0.5;
  const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
  const double tx = fx - x0, ty = fy - y0;
  // Corner k = 2 j + i is texel (x0 + i, y0 + j).
  std::array<Texel4, 4> corner;
  std::array<double, 4> weight;
  for (int k = 0; k < 4; ++k) {
    const int i = k % 2, j = k / 2;
    corner[k] = *texelValue(map, face, x0 + i, y0 + j);
    weight[k] = (i ? tx : 1 - tx) * (j ? ty : 1 - ty);
  }
  // The sides of the block that span a jump: longer than three times its shortest side (a
  // conformal map keeps the block nearly square, even where it magnifies without bound next to a
  // display corner) and than `jumpChord`. A side's texels are those joined by the other sides.
  // Lengths are chords of the unit directions, as in confvis_warp.glsl (and no atan2 per side).
  std::array<Vec3d, 4> unit;
  for (int k = 0; k < 4; ++k) unit[k] = normalized(corner[k].direction());
  constexpr std::array<int, 4> ring{0, 1, 3, 2};  // around the block
  std::array<double, 4> sideLength;
  for (int e = 0; e < 4; ++e) sideLength[e] = norm(unit[ring[e]] - unit[ring[(e + 1) % 4]]);
  const double longSide =
      std::max(3.0 * *std::min_element(sideLength.begin(), sideLength.end()), jumpChord);
  auto sideOf = [&](int anchor) {
    std::array<bool, 4> joined{};
    joined[anchor] = true;
    for (int pass = 0; pass < 2; ++pass)  // twice around reaches every joined texel
      for (int e = 0; e < 4; ++e) {
        const int p = ring[e], q = ring[(e + 1) % 4];
        if (sideLength[e] <= longSide && (joined[p] || joined[q])) joined[p] = joined[q] = true;
      }
    return joined;
  };
  int nearest = 0;
  for (int k = 1; k < 4; ++k)
    if (weight[k] > weight[nearest]) nearest = k;
  int anchor = nearest;
  if (side != 0) {
    const std::array<bool, 4> nearSide = sideOf(nearest);
    anchor = -1;
    for (int k = 0; k < 4; ++k)
      if (!nearSide[k] && (anchor < 0 || weight[k] > weight[anchor])) anchor = k;
    if (anchor < 0) return std::nullopt;
  }
  const std::array<bool, 4> member = sideOf(anchor);
  std::array<bool, 4> known = member;
  std::array<Texel4, 4> value = corner;
  bool straddles = false;
  for (int k = 0; k < 4; ++k) straddles |= !member[k];
  // Corner k from the other three: a parallelogram (i is k's column, j its row).
  auto fromParallelogram = [&](int k, const std::array<bool, 4>& given) {
    const int i = k % 2, j = k / 2;
    const int inRow = 2 * j + (1 - i), inColumn = 2 * (1 - j) + i, diagonal = 3 - k;
    if (!given[inRow] || !given[inColumn] || !given[diagonal]) return false;
    value[k] = combine(combine(value[inRow], 1, value[inColumn], 1), 1, value[diagonal], -1);
    known[k] = true;
    return true;
  };
  if (straddles) {
    // Corners of the other side, from this side's corners: the parallelogram of the three
    // others, else the line from the neighbour in the same row or column through the texel
    // beyond it (outside the footprint), averaged where both exist.
    for (int k = 0; k < 4; ++k) {
      if (member[k] || fromParallelogram(k, member)) continue;
      const int i = k % 2, j = k / 2;
      const int inRow = 2 * j + (1 - i), inColumn = 2 * (1 - j) + i;
      Texel4 sum;
      int lines = 0;
      auto extendLine = [&](int neighbour, int beyondX, int beyondY) {
        if (!member[neighbour]) return;
        const std::optional<Texel4> beyond = texelValue(map, face, beyondX, beyondY);
        if (!beyond || norm(normalized(beyond->direction()) - unit[neighbour]) > longSide) return;
        sum = combine(sum, 1, combine(corner[neighbour], 2, *beyond, -1), 1);
        ++lines;
      };
      // The neighbour in the row sits at x0 + (1 - i); the texel beyond it one more step away.
      extendLine(inRow, x0 + (1 - i) + (1 - 2 * i), y0 + j);
      extendLine(inColumn, x0 + i, y0 + (1 - j) + (1 - 2 * j));
      if (lines > 0) {
        value[k] = scaled(sum, 1.0 / lines);
        known[k] = true;
      }
    }
    // The corner diagonal to a lone member, from the two it extrapolated.
    for (int k = 0; k < 4; ++k)
      if (!known[k]) fromParallelogram(k, known);
  }
  Vec3d sum{};
  double alpha = 0, memberWeight = 0;
  for (int k = 0; k < 4; ++k) {
    if (known[k]) sum = sum + weight[k] * value[k].direction();
    if (member[k]) {
      alpha += weight[k] * corner[k].v[3];
      memberWeight += weight[k];
    }
  }
  OneSidedSample out;
  const double length = norm(sum);
  out.direction = length > 0 ? (1.0 / length) * sum : normalized(corner[anchor].direction());
  // Side 1's texels can all weigh 0 (v on a texel centre line): its anchor's alpha stands in.
  out.alpha = static_cast<float>(memberWeight > 0 ? alpha / memberWeight : corner[anchor].v[3]);
  out.straddles = straddles;
  std::array<Vec3d, 4> known3;
  for (int k = 0; k < 4; ++k)
    if (known[k]) known3[k] = member[k] ? unit[k] : normalized(value[k].direction());
  double chord = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b)
      if (known[a] && known[b]) chord = std::max(chord, norm(known3[a] - known3[b]));
  out.footprintSpread = 2 * std::asin(std::min(1.0, 0.5 * chord));
  return out;
}

}  // namespace confvis::detail
