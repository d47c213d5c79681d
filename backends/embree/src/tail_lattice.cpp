#include "tail_lattice.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>

#include "tail_blend.hpp"

namespace confvis::embree {

namespace {

// An upper bound of asin(x), x in [0, 1], without the library call: the series' coefficients
// from x^3 on are at most 1/6, so asin(x) <= x + x^3 / (6 (1 - x^2)); a relative margin covers
// float rounding. Near 1 (cells far wider than any wall's), the library's value with the margin.
float asinAbove(float x) {
  if (!(x < 0.5f)) return 1.0001f * std::asin(std::min(1.0f, x));
  return 1.0001f * (x + x * x * x / (6.0f * (1.0f - x * x)));
}

}  // namespace

TailLattice::TailLattice(const CameraRays& rays, const TileJob& job, int x0, int y0, int x1,
                         int y1, float tolerancePixels)
    : rays_(rays),
      pixelToWall_(static_cast<float>(job.pixelToWall.x), static_cast<float>(job.pixelToWall.y)),
      x0_(x0),
      y0_(y0),
      cellsAcross_((x1 - x0 + kTailCellPixels - 1) / kTailCellPixels),
      cellsDown_((y1 - y0 + kTailCellPixels - 1) / kTailCellPixels),
      tolerancePixels_(tolerancePixels),
      simd_(job.shading.simd),
      // Packets (blocks of 4 x 2 from the tile's corner) must each lie inside one cell.
      usable_(job.tileSize % kTailCellPixels == 0 && kTailCellPixels % kBlockColumns == 0 &&
              kTailCellPixels % kBlockRows == 0) {}

void TailLattice::build() {
  built_ = true;
  const int across = cellsAcross_ + 1, down = cellsDown_ + 1;
  const int nodeCount = across * down, cellCount = cellsAcross_ * cellsDown_;
  // The positions: every cell corner, then every cell centre, in wall pixels.
  std::vector<float> wallX, wallY;
  wallX.reserve(static_cast<std::size_t>(nodeCount + cellCount));
  wallY.reserve(static_cast<std::size_t>(nodeCount + cellCount));
  for (int j = 0; j < down; ++j)
    for (int i = 0; i < across; ++i) {
      wallX.push_back(static_cast<float>(x0_ + kTailCellPixels * i) * pixelToWall_.x);
      wallY.push_back(static_cast<float>(y0_ + kTailCellPixels * j) * pixelToWall_.y);
    }
  constexpr float kHalfCell = 0.5f * kTailCellPixels;
  for (int j = 0; j < cellsDown_; ++j)
    for (int i = 0; i < cellsAcross_; ++i) {
      wallX.push_back((static_cast<float>(x0_ + kTailCellPixels * i) + kHalfCell) * pixelToWall_.x);
      wallY.push_back((static_cast<float>(y0_ + kTailCellPixels * j) + kHalfCell) * pixelToWall_.y);
    }
  const int total = nodeCount + cellCount;
  std::vector<Point> points(static_cast<std::size_t>(total));
  for (int first = 0; first < total; first += kPacketSize) {
    const int count = std::min(kPacketSize, total - first);
    alignas(32) Lanes px, py;
    for (int lane = 0; lane < kPacketSize; ++lane) {
      const auto at = static_cast<std::size_t>(first + std::min(lane, count - 1));
      px[lane] = wallX[at], py[lane] = wallY[at];
    }
    CameraRays::TailGeometry geometry;
    alignas(32) std::array<float, 6 * kPacketSize> tails;
    rays_.tailsAt(px.data(), py.data(), count, geometry, tails.data());
    for (int lane = 0; lane < count; ++lane) {
      const auto component = [&](int k) { return tails[static_cast<std::size_t>(k * kPacketSize + lane)]; };
      Point& point = points[static_cast<std::size_t>(first + lane)];
      point.direction = {component(0), component(1), component(2)};
      const glm::vec3 start(component(3), component(4), component(5));
      point.offset = start - glm::dot(start, point.direction) * point.direction;
      point.startDistance = glm::length(start);
      point.u = {geometry.ux[lane], geometry.uy[lane], geometry.uz[lane]};
      point.h = geometry.h[lane];
    }
  }
  nodes_.assign(points.begin(), points.begin() + nodeCount);
  pass_.assign(static_cast<std::size_t>(cellCount), 0);
  lit_.assign(static_cast<std::size_t>(cellCount), 0);
  cells_.assign(static_cast<std::size_t>(cellCount), TailCell{});
  const glm::vec3 eye = rays_.eyeFromCentre();
  const float eyeDistance = glm::length(eye);
  const float sinAsymptote = static_cast<float>(std::sin(kAsymptoteAngle));
  const float tanAsymptote = static_cast<float>(std::tan(kAsymptoteAngle));
  // The lattice's second differences along x and y at every node with both neighbours in the
  // tile, once per node (each serves up to four cells): the turn's and the shift's lengths, which
  // a cell weighs by its own reach.
  struct Second {
    float turn = 0.0f, shift = 0.0f;
    bool seen = false;  // the node has both neighbours along the axis
  };
  std::vector<std::array<Second, 2>> seconds(static_cast<std::size_t>(nodeCount));
  for (int nj = 0; nj < down; ++nj)
    for (int ni = 0; ni < across; ++ni)
      for (int axis = 0; axis < 2; ++axis) {
        const int di = axis == 0 ? 1 : 0, dj = 1 - di;
        if (ni - di < 0 || nj - dj < 0 || ni + di >= across || nj + dj >= down) continue;
        const Point& before = nodes_[static_cast<std::size_t>((nj - dj) * across + ni - di)];
        const Point& at = nodes_[static_cast<std::size_t>(nj * across + ni)];
        const Point& after = nodes_[static_cast<std::size_t>((nj + dj) * across + ni + di)];
        Second& second = seconds[static_cast<std::size_t>(nj * across + ni)][axis];
        second.turn = glm::length(before.direction - 2.0f * at.direction + after.direction);
        second.shift = glm::length(before.offset - 2.0f * at.offset + after.offset);
        second.seen = true;
      }
  // One output pixel's angle (across the ray, the smaller of across and down), the smallest at
  // the tile's corners: it changes by a few per cent over a tile and peaks where the wall is
  // nearest the eye, so that no point of the tile sees a smaller one.
  const auto pixelAngleAt = [&](float wallPixelX, float wallPixelY) {
    const glm::vec3 toWall =
        rays_.rayBase() + wallPixelX * rays_.rayStepX() + wallPixelY * rays_.rayStepY();
    const float distance = glm::length(toWall);
    const glm::vec3 unit = toWall / distance;
    const auto across1 = [&](const glm::vec3& step) {
      return glm::length(step - glm::dot(step, unit) * unit) / distance;
    };
    return std::min(across1(pixelToWall_.x * rays_.rayStepX()),
                    across1(pixelToWall_.y * rays_.rayStepY()));
  };
  const float tileLeft = static_cast<float>(x0_) * pixelToWall_.x;
  const float tileTop = static_cast<float>(y0_) * pixelToWall_.y;
  const float tileRight = static_cast<float>(x0_ + kTailCellPixels * cellsAcross_) * pixelToWall_.x;
  const float tileBottom = static_cast<float>(y0_ + kTailCellPixels * cellsDown_) * pixelToWall_.y;
  const float pixelAngle =
      std::min(std::min(pixelAngleAt(tileLeft, tileTop), pixelAngleAt(tileRight, tileTop)),
               std::min(pixelAngleAt(tileLeft, tileBottom), pixelAngleAt(tileRight, tileBottom)));
  // The pixels' alpha does not depend on the eye: a cell whose grid samples are all lit needs
  // no lookup per sample (an override's alpha is its rays', not the wall pixel's); the whole
  // tile asked first.
  const WallMapGrid* grid = rays_.overridden() ? nullptr : rays_.mapGrid();
  const bool tileLit = grid && grid->litThroughout(tileLeft, tileTop, tileRight, tileBottom);
  for (int cell = 0; cell < cellCount; ++cell) {
    const int i = cell % cellsAcross_, j = cell / cellsAcross_;
    const Point& centre = points[static_cast<std::size_t>(nodeCount + cell)];
    const std::array<int, 4> cornerNodes = {j * across + i, j * across + i + 1,
                                            (j + 1) * across + i, (j + 1) * across + i + 1};
    glm::vec3 direction(0.0f), offset(0.0f);
    float nearestStart = std::numeric_limits<float>::infinity(), widestOffset = 0.0f;
    float chordSquared = 0.0f;  // the cell's angular radius from the eye, squared (farthest corner)
    for (int node : cornerNodes) {
      const Point& corner = nodes_[static_cast<std::size_t>(node)];
      direction += 0.25f * corner.direction;
      offset += 0.25f * corner.offset;
      nearestStart = std::min(nearestStart, corner.startDistance);
      widestOffset = std::max(widestOffset, glm::length(corner.offset));
      const glm::vec3 chord = corner.u - centre.u;
      chordSquared = std::max(chordSquared, glm::dot(chord, chord));
    }
    // h = |e - c| sin(angle(u, e - c)) is 1-Lipschitz in the angle between rays times |e - c|:
    // within the cell it lies within `spread` of the centre's (the angle from the chord; a
    // relative margin for float rounding).
    const float angularRadius = 2.0f * asinAbove(0.5f * std::sqrt(chordSquared));
    const float spread = eyeDistance * angularRadius;
    // The smallest reach in the cell (what the check weighs the offsets' error by) and the
    // largest (what the cell's samples report: CameraRays::exactTails' reach bounded above,
    // 1.0001 |e - c| at least as there, so that a packet is straight only where every curve of
    // it bends inside the empty ball).
    const float reach = std::max(eyeDistance, (centre.h - spread) / sinAsymptote);
    // How far along its blended line each sample starts from the blended offset O: by the
    // triangle inequality the start lies within |O| + along <= the corners' largest |O| + along
    // = their nearest start of c, inside the cell's reach (no nearer the scene than the curves'
    // own starts); a per-mille margin for rounding. Starting at O itself, a few cm from c,
    // would make Embree cross the scene's bounding boxes from inside (about 10 % slower).
    TailCell& blend = cells_[static_cast<std::size_t>(cell)];
    blend.along = 0.999f * std::max(0.0f, nearestStart - widestOffset);
    blend.reach =
        1.0001f * std::max(eyeDistance, 1.00001f * (centre.h + spread) / sinAsymptote);
    // A sample on a line through c (h <= along tan(asymptote), along <= |e - c|) needs its whole
    // curve traced (infinite reach): a cell that may hold one is not interpolated.
    const bool offLine = centre.h - spread > 1.01f * eyeDistance * tanAsymptote;
    // The line's angular error: the turn plus the offset's shift over the nearest hit.
    const auto angle = [reach](const glm::vec3& turn, const glm::vec3& shift) {
      return glm::length(turn) + glm::length(shift) / reach;
    };
    // At the centre; and from the lattice's second differences along each axis (the bilinear
    // blend's error is at most (|f_xx| + |f_yy|) / 8 in cell units, which the centre alone
    // misses where the two cancel, a saddle): at the cell's corners' nodes that have both
    // neighbours in the tile. A cell with none along an axis (a tile one cell wide) is not
    // interpolated.
    float alongX = 0.0f, alongY = 0.0f;
    bool seenX = false, seenY = false;
    for (int node : cornerNodes) {
      const std::array<Second, 2>& second = seconds[static_cast<std::size_t>(node)];
      if (second[0].seen) {
        seenX = true;
        alongX = std::max(alongX, second[0].turn + second[0].shift / reach);
      }
      if (second[1].seen) {
        seenY = true;
        alongY = std::max(alongY, second[1].turn + second[1].shift / reach);
      }
    }
    const float error =
        std::max(angle(glm::normalize(direction) - centre.direction, offset - centre.offset),
                 seenX && seenY ? 0.125f * (alongX + alongY)
                                : std::numeric_limits<float>::infinity());
    const float left = static_cast<float>(x0_ + kTailCellPixels * i) * pixelToWall_.x;
    const float top = static_cast<float>(y0_ + kTailCellPixels * j) * pixelToWall_.y;
    // The blend's corners and place (tail_blend.hpp).
    for (std::size_t k = 0; k < 4; ++k) {
      const Point& corner = nodes_[static_cast<std::size_t>(cornerNodes[k])];
      for (int component = 0; component < 3; ++component) {
        blend.corners[k][static_cast<std::size_t>(component)] = corner.direction[component];
        blend.corners[k][static_cast<std::size_t>(3 + component)] = corner.offset[component];
      }
    }
    blend.left = left, blend.top = top;
    blend.perX = 1.0f / (kTailCellPixels * pixelToWall_.x);
    blend.perY = 1.0f / (kTailCellPixels * pixelToWall_.y);
    lit_[static_cast<std::size_t>(cell)] =
        tileLit || (grid && grid->litThroughout(left, top, left + kTailCellPixels * pixelToWall_.x,
                                                top + kTailCellPixels * pixelToWall_.y));
    pass_[static_cast<std::size_t>(cell)] =
        std::isinf(tolerancePixels_) || (offLine && error <= tolerancePixels_ * pixelAngle) ? 1
                                                                                         : 0;
  }
}

bool TailLattice::interpolated(int x, int y) {
  if (!usable_) return false;
  if (!built_) build();
  return pass_[static_cast<std::size_t>(cellIndex(x, y))] != 0;
}

float TailLattice::tails(const PacketSamples& samples, const float* px, const float* py,
                         float* run, float* reach) {
  if (!interpolated(samples.x, samples.y))
    return rays_.exactTails(px, py, samples.count, run, reach);
  const int cell = cellIndex(samples.x, samples.y);
  const TailCell& corners = cells_[static_cast<std::size_t>(cell)];
  if (lit_[static_cast<std::size_t>(cell)])
    return blendTails(simd_, corners, px, py, nullptr, samples.count, run, reach);
  alignas(32) Lanes alpha;
  rays_.pixelAlpha(px, py, samples.count, alpha.data());
  return blendTails(simd_, corners, px, py, alpha.data(), samples.count, run, reach);
}

}  // namespace confvis::embree
