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
// float rounding. From 1/2 on (cells far wider than any wall's), pi / 2 and a little.
float asinAbove(float x) {
  const float small = std::min(x, 0.5f);  // a select, so that the check's loop vectorises
  return x < 0.5f ? 1.0001f * (small + small * small * small / (6.0f * (1.0f - small * small)))
                  : 1.5709f;
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
              kTailCellPixels % kBlockRows == 0) {
  const glm::mat3& m = rays.rotation();
  for (int column = 0; column < 3; ++column)
    for (int row = 0; row < 3; ++row)
      placement_.rotation[static_cast<std::size_t>(3 * column + row)] = m[column][row];
  const glm::vec3& c = rays.placedCentre();
  placement_.centre = {c.x, c.y, c.z};
}

void TailLattice::build() {
  built_ = true;
  const int across = cellsAcross_ + 1, down = cellsDown_ + 1;
  const int nodeCount = across * down, cellCount = cellsAcross_ * cellsDown_;
  const int padded = (nodeCount + kPacketSize - 1) / kPacketSize * kPacketSize;
  // The positions: every cell corner, in wall pixels (the last repeated up to a whole packet).
  std::vector<float> wallX(static_cast<std::size_t>(padded)), wallY(static_cast<std::size_t>(padded));
  for (int j = 0; j < down; ++j)
    for (int i = 0; i < across; ++i) {
      wallX[static_cast<std::size_t>(j * across + i)] = static_cast<float>(x0_ + kTailCellPixels * i) * pixelToWall_.x;
      wallY[static_cast<std::size_t>(j * across + i)] = static_cast<float>(y0_ + kTailCellPixels * j) * pixelToWall_.y;
    }
  for (int at = nodeCount; at < padded; ++at)
    wallX[static_cast<std::size_t>(at)] = wallX[static_cast<std::size_t>(nodeCount - 1)],
    wallY[static_cast<std::size_t>(at)] = wallY[static_cast<std::size_t>(nodeCount - 1)];
  // The exact tails there, structure of arrays: unit direction D, the start's offset across it
  // O = S - (S.D) D, the physical ray's direction u, the eye's distance h across it, |S|, |O|.
  enum Field { kDx, kDy, kDz, kOx, kOy, kOz, kUx, kUy, kUz, kH, kStart, kOffset, kFields };
  std::vector<float> fields(static_cast<std::size_t>(kFields * padded));
  const auto field = [&](int f) { return fields.data() + static_cast<std::size_t>(f * padded); };
  for (int first = 0; first < padded; first += kPacketSize) {
    CameraRays::TailGeometry geometry;
    alignas(32) std::array<float, 6 * kPacketSize> tails;
    rays_.tailsAt(&wallX[static_cast<std::size_t>(first)], &wallY[static_cast<std::size_t>(first)],
                  std::min(kPacketSize, nodeCount - first), geometry, tails.data());
    const auto component = [&](int k, int lane) {
      return tails[static_cast<std::size_t>(k * kPacketSize + lane)];
    };
    for (int lane = 0; lane < kPacketSize; ++lane) {
      const float dx = component(0, lane), dy = component(1, lane), dz = component(2, lane);
      const float sx = component(3, lane), sy = component(4, lane), sz = component(5, lane);
      const float along = sx * dx + sy * dy + sz * dz;
      const float ox = sx - along * dx, oy = sy - along * dy, oz = sz - along * dz;
      const int at = first + lane;
      field(kDx)[at] = dx, field(kDy)[at] = dy, field(kDz)[at] = dz;
      field(kOx)[at] = ox, field(kOy)[at] = oy, field(kOz)[at] = oz;
      field(kUx)[at] = geometry.ux[lane], field(kUy)[at] = geometry.uy[lane];
      field(kUz)[at] = geometry.uz[lane], field(kH)[at] = geometry.h[lane];
      field(kStart)[at] = std::sqrt(sx * sx + sy * sy + sz * sz);
      field(kOffset)[at] = std::sqrt(ox * ox + oy * oy + oz * oz);
    }
  }
  const float* dX = field(kDx); const float* dY = field(kDy); const float* dZ = field(kDz);
  const float* oX = field(kOx); const float* oY = field(kOy); const float* oZ = field(kOz);
  const float* uX = field(kUx); const float* uY = field(kUy); const float* uZ = field(kUz);
  const float* hs = field(kH); const float* starts = field(kStart); const float* offsets = field(kOffset);
  pass_.assign(static_cast<std::size_t>(cellCount), 0);
  lit_.assign(static_cast<std::size_t>(cellCount), 0);
  cells_.assign(static_cast<std::size_t>(cellCount), TailCell{});
  const glm::vec3 eye = rays_.eyeFromCentre();
  const float eyeDistance = glm::length(eye);
  const float sinAsymptote = static_cast<float>(std::sin(kAsymptoteAngle));
  const float tanAsymptote = static_cast<float>(std::tan(kAsymptoteAngle));
  // The lattice's second differences along x and y at every node with both neighbours in the
  // tile, once per node (each serves up to four cells): the turn's and the shift's lengths, which
  // a cell weighs by its own reach; a negative turn where the node lacks a neighbour.
  std::vector<float> seconds(static_cast<std::size_t>(4 * nodeCount), -1.0f);
  float* turnX = seconds.data();
  float* shiftX = turnX + nodeCount;
  float* turnY = shiftX + nodeCount;
  float* shiftY = turnY + nodeCount;
  const auto second = [&](int before, int at, int after, float& turn, float& shift) {
    const auto length = [&](const float* x, const float* y, const float* z) {
      const float ex = x[before] - 2.0f * x[at] + x[after];
      const float ey = y[before] - 2.0f * y[at] + y[after];
      const float ez = z[before] - 2.0f * z[at] + z[after];
      return std::sqrt(ex * ex + ey * ey + ez * ez);
    };
    turn = length(dX, dY, dZ);
    shift = length(oX, oY, oZ);
  };
  for (int nj = 0; nj < down; ++nj)
    for (int ni = 0; ni < across; ++ni) {
      const int n = nj * across + ni;
      if (ni > 0 && ni + 1 < across) second(n - 1, n, n + 1, turnX[n], shiftX[n]);
      if (nj > 0 && nj + 1 < down) second(n - across, n, n + across, turnY[n], shiftY[n]);
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
  const bool everyCell = std::isinf(tolerancePixels_);
  const float bound = tolerancePixels_ * pixelAngle;
  constexpr float kInfinity = std::numeric_limits<float>::infinity();
  // The check, cell by cell along each row (structure of arrays: the row's loop vectorises).
  std::vector<float> cellAlong(static_cast<std::size_t>(cellCount)), cellReach(cellAlong.size());
  for (int j = 0; j < cellsDown_; ++j) {
    const int row = j * across;  // the node at the row's first cell's top-left corner
    const int firstCell = j * cellsAcross_;
    for (int i = 0; i < cellsAcross_; ++i) {
      const int corners[4] = {row + i, row + i + 1, row + across + i, row + across + i + 1};
      float directionX = 0.0f, directionY = 0.0f, directionZ = 0.0f;
      float offsetX = 0.0f, offsetY = 0.0f, offsetZ = 0.0f;
      float nearestStart = kInfinity, widestOffset = 0.0f;
      float hMax = 0.0f, hMin = kInfinity;
      for (int n : corners) {
        directionX += 0.25f * dX[n], directionY += 0.25f * dY[n], directionZ += 0.25f * dZ[n];
        offsetX += 0.25f * oX[n], offsetY += 0.25f * oY[n], offsetZ += 0.25f * oZ[n];
        nearestStart = std::min(nearestStart, starts[n]);
        widestOffset = std::max(widestOffset, offsets[n]);
        hMax = std::max(hMax, hs[n]);
        hMin = std::min(hMin, hs[n]);
      }
      // The cell's angular diameter seen from the eye (its rays' directions span a convex
      // quadrilateral, whose widest chord joins two corners), squared.
      float chordSquared = 0.0f;
      for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b) {
          const int na = corners[a], nb = corners[b];
          const float cx = uX[na] - uX[nb], cy = uY[na] - uY[nb], cz = uZ[na] - uZ[nb];
          chordSquared = std::max(chordSquared, cx * cx + cy * cy + cz * cz);
        }
      // h = |e - c| sin(angle(u, e - c)) is 1-Lipschitz in the angle between rays times |e - c|:
      // every sample lies within the diameter of each corner, so its h lies within `spread` of
      // every corner's: at least the largest less it, at most the smallest plus it.
      const float spread = eyeDistance * 2.0f * asinAbove(0.5f * std::sqrt(chordSquared));
      // (h is at most |e - c|: a bound past it would report a reach beyond every curve's,
      // outside the ball the clearance query reaches, and march the cell's packets as curves.)
      const float hLow = hMax - spread, hHigh = std::min(hMin + spread, eyeDistance);
      // The smallest reach in the cell (what the check weighs the offsets' error by) and the
      // largest (what the cell's samples report: CameraRays::exactTails' reach bounded above,
      // 1.0001 |e - c| at least as there, so that a packet is straight only where every curve
      // of it bends inside the empty ball).
      const float reach = std::max(eyeDistance, hLow / sinAsymptote);
      cellReach[static_cast<std::size_t>(firstCell + i)] =
          1.0001f * std::max(eyeDistance, 1.00001f * hHigh / sinAsymptote);
      // How far along its blended line each sample starts from the blended offset O: by the
      // triangle inequality the start lies within |O| + along <= the corners' largest |O| +
      // along = their nearest start of c, inside the cell's reach (no nearer the scene than
      // the curves' own starts); a per-mille margin for rounding. Starting at O itself, a few
      // cm from c, would make Embree cross the scene's bounding boxes from inside (about 10 %
      // slower).
      cellAlong[static_cast<std::size_t>(firstCell + i)] =
          0.999f * std::max(0.0f, nearestStart - widestOffset);
      // A sample on a line through c (h <= along tan(asymptote), along <= |e - c|) needs its
      // whole curve traced (infinite reach): a cell that may hold one is not interpolated.
      const bool offLine = hLow > 1.01f * eyeDistance * tanAsymptote;
      // The line's angular error, the turn plus the offset's shift over the nearest hit, from
      // the lattice's second differences along each axis (the bilinear blend's error is at most
      // (|f_xx| + |f_yy|) / 8 in cell units): at the cell's corners' nodes that have both
      // neighbours in the tile. A cell with none along an axis (a tile one cell wide) is not
      // interpolated. (The exact centre the blend was also checked against until stereo24
      // changed no cell at 24-480 px walls: EmbreeTailLattice.*.)
      float alongX = -1.0f, alongY = -1.0f;  // negative: no node with both neighbours
      for (int n : corners) {
        alongX = std::max(alongX, turnX[n] < 0.0f ? -1.0f : turnX[n] + shiftX[n] / reach);
        alongY = std::max(alongY, turnY[n] < 0.0f ? -1.0f : turnY[n] + shiftY[n] / reach);
      }
      const float error = alongX >= 0.0f && alongY >= 0.0f ? 0.125f * (alongX + alongY) : kInfinity;
      pass_[static_cast<std::size_t>(firstCell + i)] =
          everyCell || (offLine && error <= bound) ? 1 : 0;
    }
  }
  // The pixels' alpha does not depend on the eye: a cell whose grid samples are all lit needs
  // no lookup per sample (an override's alpha is its rays', not the wall pixel's); the whole
  // tile asked first. And each cell's blend record (tail_blend.hpp).
  const WallMapGrid* grid = rays_.overridden() ? nullptr : rays_.mapGrid();
  const bool tileLit = grid && grid->litThroughout(tileLeft, tileTop, tileRight, tileBottom);
  for (int cell = 0; cell < cellCount; ++cell) {
    const int i = cell % cellsAcross_, j = cell / cellsAcross_;
    const int corners[4] = {j * across + i, j * across + i + 1, (j + 1) * across + i,
                            (j + 1) * across + i + 1};
    TailCell& blend = cells_[static_cast<std::size_t>(cell)];
    for (std::size_t k = 0; k < 4; ++k) {
      const int n = corners[k];
      blend.corners[k] = {dX[n], dY[n], dZ[n], oX[n], oY[n], oZ[n]};
    }
    const float left = static_cast<float>(x0_ + kTailCellPixels * i) * pixelToWall_.x;
    const float top = static_cast<float>(y0_ + kTailCellPixels * j) * pixelToWall_.y;
    blend.left = left, blend.top = top;
    blend.perX = 1.0f / (kTailCellPixels * pixelToWall_.x);
    blend.perY = 1.0f / (kTailCellPixels * pixelToWall_.y);
    blend.reach = cellReach[static_cast<std::size_t>(cell)];
    blend.along = cellAlong[static_cast<std::size_t>(cell)];
    lit_[static_cast<std::size_t>(cell)] =
        tileLit || (grid && grid->litThroughout(left, top, left + kTailCellPixels * pixelToWall_.x,
                                                top + kTailCellPixels * pixelToWall_.y));
  }
}

bool TailLattice::interpolated(int x, int y) {
  if (!usable_) return false;
  if (!built_) build();
  return pass_[static_cast<std::size_t>(cellIndex(x, y))] != 0;
}

bool TailLattice::straightRays(const PacketSamples& samples, const float* px, const float* py,
                               double emptyRadius, const TailRays& rays) {
  if (!interpolated(samples.x, samples.y)) return false;
  const int cell = cellIndex(samples.x, samples.y);
  const TailCell& corners = cells_[static_cast<std::size_t>(cell)];
  if (!(corners.reach < emptyRadius)) return false;
  if (lit_[static_cast<std::size_t>(cell)]) {
    blendRays(simd_, corners, px, py, nullptr, samples.count, placement_, rays);
    return true;
  }
  alignas(32) Lanes alpha;
  rays_.pixelAlpha(px, py, samples.count, alpha.data());
  blendRays(simd_, corners, px, py, alpha.data(), samples.count, placement_, rays);
  return true;
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
