// The exact stereo tails' per-sample blend (tail_blend.hpp) against a scalar reference in
// double: bilinear weights, the direction normalised, the start O + along D, masking; and the
// baseline and AVX2 builds bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "../src/tail_blend.hpp"

namespace confvis::embree {
namespace {

// A cell whose corners hold unit directions a few degrees apart and offsets a few cm across
// them, at a random place and size.
TailCell randomCell(std::mt19937& random) {
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  TailCell cell;
  const glm::vec3 axis = glm::normalize(glm::vec3(unit(random), unit(random), unit(random)));
  for (auto& corner : cell.corners) {
    const glm::vec3 d = glm::normalize(axis + 0.05f * glm::vec3(unit(random), unit(random), unit(random)));
    glm::vec3 o = 0.03f * glm::vec3(unit(random), unit(random), unit(random));
    o -= glm::dot(o, d) * d;
    corner = {d.x, d.y, d.z, o.x, o.y, o.z};
  }
  cell.left = 100.0f + 50.0f * unit(random), cell.top = 80.0f + 50.0f * unit(random);
  const float size = 4.0f * (1.5f + unit(random));
  cell.perX = 1.0f / size, cell.perY = 1.0f / (size * 1.1f);
  cell.reach = 8.0f + unit(random), cell.along = 7.0f + unit(random);
  return cell;
}

struct Packet {
  std::array<float, kPacketSize> px{}, py{}, alpha{};
};

Packet randomPacket(const TailCell& cell, std::mt19937& random) {
  std::uniform_real_distribution<float> within(0.0f, 1.0f), alpha(0.0f, 1.0f);
  Packet p;
  for (int lane = 0; lane < kPacketSize; ++lane) {
    p.px[lane] = cell.left + within(random) / cell.perX;
    p.py[lane] = cell.top + within(random) / cell.perY;
    p.alpha[lane] = alpha(random);
  }
  return p;
}

// The reference, in double: `swapCorners` exchanges the (right, top) and (left, bottom) corners
// (a broken blend the comparison must catch).
void reference(const TailCell& cell, const Packet& p, int lane, bool swapCorners,
               glm::dvec3& direction, glm::dvec3& start) {
  const double tx = (p.px[lane] - cell.left) * static_cast<double>(cell.perX);
  const double ty = (p.py[lane] - cell.top) * static_cast<double>(cell.perY);
  const std::array<double, 4> w = {(1 - tx) * (1 - ty), swapCorners ? (1 - tx) * ty : tx * (1 - ty),
                                   swapCorners ? tx * (1 - ty) : (1 - tx) * ty, tx * ty};
  glm::dvec3 d(0.0), o(0.0);
  for (std::size_t k = 0; k < 4; ++k) {
    d += w[k] * glm::dvec3(cell.corners[k][0], cell.corners[k][1], cell.corners[k][2]);
    o += w[k] * glm::dvec3(cell.corners[k][3], cell.corners[k][4], cell.corners[k][5]);
  }
  direction = glm::normalize(d);
  start = o + static_cast<double>(cell.along) * direction;
}

double worstDeviation(const TailCell& cell, const Packet& p, const std::array<float, 6 * kPacketSize>& run,
                      bool swapCorners) {
  double worst = 0.0;
  for (int lane = 0; lane < kPacketSize; ++lane) {
    if (!(p.alpha[lane] >= 0.5f)) continue;
    glm::dvec3 direction, start;
    reference(cell, p, lane, swapCorners, direction, start);
    const auto at = [&](int k) { return static_cast<double>(run[static_cast<std::size_t>(k * kPacketSize + lane)]); };
    worst = std::max(worst, glm::length(glm::dvec3(at(0), at(1), at(2)) - direction));
    worst = std::max(worst, glm::length(glm::dvec3(at(3), at(4), at(5)) - start) / cell.along);
  }
  return worst;
}

TEST(EmbreeTailBlend, BlendsLikeTheReferenceAndMasksUnlitLanes) {
  std::mt19937 random(23);
  double worst = 0.0;
  int litPackets = 0, caughtSwaps = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const TailCell cell = randomCell(random);
    const Packet p = randomPacket(cell, random);
    std::array<float, 6 * kPacketSize> run;
    std::array<float, kPacketSize> reach;
    const float packetReach = sse2::blendTails(cell, p.px.data(), p.py.data(), p.alpha.data(),
                                               kPacketSize, run.data(), reach.data());
    worst = std::max(worst, worstDeviation(cell, p, run, false));
    caughtSwaps += worstDeviation(cell, p, run, true) > 1e-3 ? 1 : 0;
    bool anyLit = false;
    for (int lane = 0; lane < kPacketSize; ++lane) {
      const bool lit = p.alpha[lane] >= 0.5f;
      anyLit = anyLit || lit;
      EXPECT_EQ(reach[lane], lit ? cell.reach : 0.0f);
      for (int k = 0; k < 6 && !lit; ++k) EXPECT_EQ(run[static_cast<std::size_t>(k * kPacketSize + lane)], 0.0f);
    }
    EXPECT_EQ(packetReach, anyLit ? cell.reach : 0.0f);
    litPackets += anyLit ? 1 : 0;
  }
  EXPECT_LT(worst, 1e-6);
  // A broken blend (two corners swapped) is caught in nearly every packet with lit lanes: the
  // comparison has teeth.
  EXPECT_GT(caughtSwaps, 0.95 * litPackets);
}

TEST(EmbreeTailBlend, WithoutAlphaTheFirstCountLanesAreLit) {
  std::mt19937 random(5);
  const TailCell cell = randomCell(random);
  const Packet p = randomPacket(cell, random);
  std::array<float, 6 * kPacketSize> run, withAlpha;
  std::array<float, kPacketSize> reach, reachWithAlpha, firstFive{};
  for (int lane = 0; lane < 5; ++lane) firstFive[lane] = 1.0f;
  EXPECT_EQ(sse2::blendTails(cell, p.px.data(), p.py.data(), nullptr, 5, run.data(), reach.data()),
            cell.reach);
  sse2::blendTails(cell, p.px.data(), p.py.data(), firstFive.data(), kPacketSize, withAlpha.data(),
                   reachWithAlpha.data());
  EXPECT_EQ(run, withAlpha);
  EXPECT_EQ(reach, reachWithAlpha);
  EXPECT_EQ(reach[4], cell.reach);
  EXPECT_EQ(reach[5], 0.0f);
}

TEST(EmbreeTailBlend, BaselineAndAvx2BuildsAgreeBitForBit) {
  if (detectedSimdLevel() != SimdLevel::Avx2) GTEST_SKIP() << "no AVX2 here";
#if defined(__x86_64__)  // CMakeLists.txt builds the AVX2 variant there
  std::mt19937 random(7);
  for (int trial = 0; trial < 2000; ++trial) {
    const TailCell cell = randomCell(random);
    const Packet p = randomPacket(cell, random);
    std::array<float, 6 * kPacketSize> baseline, avx;
    std::array<float, kPacketSize> baselineReach, avxReach;
    sse2::blendTails(cell, p.px.data(), p.py.data(), p.alpha.data(), kPacketSize, baseline.data(),
                     baselineReach.data());
    avx2::blendTails(cell, p.px.data(), p.py.data(), p.alpha.data(), kPacketSize, avx.data(),
                     avxReach.data());
    ASSERT_EQ(baseline, avx) << "trial " << trial;
    ASSERT_EQ(baselineReach, avxReach);
  }
#endif
}

// blendRays: the tails blendTails writes, placed by the camera as camera_packet.cpp's runPacket
// places a run (m[0][r] x + m[1][r] y + m[2][r] z, origins c + that, lanes with a non-zero
// direction traced): the same floats, in both builds. A transposed rotation must differ.
TEST(EmbreeTailBlend, PlacedRaysAreTheRunsTailsPlaced) {
  std::mt19937 random(11);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  using Blend = float (*)(const TailCell&, const float*, const float*, const float*, int, float*,
                          float*);
  using Place = void (*)(const TailCell&, const float*, const float*, const float*, int,
                         const TailPlacement&, const TailRays&);
  std::vector<std::pair<Blend, Place>> builds = {{sse2::blendTails, sse2::blendRays}};
#if defined(__x86_64__)
  if (detectedSimdLevel() == SimdLevel::Avx2) builds.push_back({avx2::blendTails, avx2::blendRays});
#endif
  for (const auto& [blendTailsOf, blendRaysOf] : builds)
    for (int trial = 0; trial < 500; ++trial) {
      const TailCell cell = randomCell(random);
      const Packet p = randomPacket(cell, random);
      glm::mat3 m;
      for (int column = 0; column < 3; ++column)
        for (int row = 0; row < 3; ++row) m[column][row] = unit(random);
      const glm::vec3 c(unit(random), unit(random), unit(random));
      TailPlacement placement;
      for (int column = 0; column < 3; ++column)
        for (int row = 0; row < 3; ++row)
          placement.rotation[static_cast<std::size_t>(3 * column + row)] = m[column][row];
      placement.centre = {c.x, c.y, c.z};
      std::array<float, 6 * kPacketSize> run;
      std::array<float, kPacketSize> reach;
      blendTailsOf(cell, p.px.data(), p.py.data(), p.alpha.data(), kPacketSize, run.data(),
                   reach.data());
      std::array<std::array<float, kPacketSize>, 6> placed;  // origins, directions
      std::array<int, kPacketSize> valid;
      blendRaysOf(cell, p.px.data(), p.py.data(), p.alpha.data(), kPacketSize, placement,
                  {placed[0].data(), placed[1].data(), placed[2].data(), placed[3].data(),
                   placed[4].data(), placed[5].data(), valid.data()});
      bool transposedDiffers = false;
      for (int lane = 0; lane < kPacketSize; ++lane) {
        const auto at = [&](int k) { return run[static_cast<std::size_t>(k * kPacketSize + lane)]; };
        const float sx = at(0), sy = at(1), sz = at(2), ox = at(3), oy = at(4), oz = at(5);
        for (int r = 0; r < 3; ++r) {
          const float direction = m[0][r] * sx + m[1][r] * sy + m[2][r] * sz;
          const float origin = c[r] + (m[0][r] * ox + m[1][r] * oy + m[2][r] * oz);
          ASSERT_EQ(placed[static_cast<std::size_t>(3 + r)][static_cast<std::size_t>(lane)], direction);
          ASSERT_EQ(placed[static_cast<std::size_t>(r)][static_cast<std::size_t>(lane)], origin);
          const float transposed = m[r][0] * sx + m[r][1] * sy + m[r][2] * sz;
          transposedDiffers = transposedDiffers || transposed != direction;
        }
        ASSERT_EQ(valid[static_cast<std::size_t>(lane)], sx != 0.0f || sy != 0.0f || sz != 0.0f ? -1 : 0);
      }
      const bool anyTraced = std::find(valid.begin(), valid.end(), -1) != valid.end();
      EXPECT_EQ(transposedDiffers, anyTraced);
    }
}

}  // namespace
}  // namespace confvis::embree
