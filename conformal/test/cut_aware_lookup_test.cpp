// The one-sided lookup across a jump in a direction cube map, against a closed form: a map that
// turns each half-space about the cut plane's normal by +-alpha (so each half keeps to itself and
// the map jumps by 2 alpha across the plane).
#include <gtest/gtest.h>

#include <cmath>

#include "../src/cut_aware_lookup.hpp"
#include "confvis/conformal/baked_map_quality.hpp"

namespace confvis {
namespace {

Vec3d rotateAbout(const Vec3d& axis, double angle, const Vec3d& v) {
  // Rodrigues' formula, axis unit.
  return std::cos(angle) * v + std::sin(angle) * cross(axis, v) +
         (1 - std::cos(angle)) * dot(axis, v) * axis;
}

struct ShearedHalves {
  static constexpr int n = 64;
  static constexpr CubeFace face = CubeFace::PosZ;
  Vec3d normal{0.0};  // the cut plane normal . v = 0 runs between texel columns n/2 - 1 and n/2
  double alpha = 0.3;
  CubeMap map{n};

  ShearedHalves() {
    const Vec3d step = texelDirection(face, n / 2, n / 2, n) - texelDirection(face, n / 2 - 1, n / 2, n);
    const int axis = std::abs(step.x) >= std::abs(step.y) && std::abs(step.x) >= std::abs(step.z) ? 0
                     : std::abs(step.y) >= std::abs(step.z)                                       ? 1
                                                                                                  : 2;
    normal = Vec3d{axis == 0 ? 1.0 : 0.0, axis == 1 ? 1.0 : 0.0, axis == 2 ? 1.0 : 0.0};
    if (dot(normal, step) < 0) normal = -1.0 * normal;
    fillCubeMap(map, [&](const Vec3d& v) { return std::pair{exact(v, dot(normal, v) > 0), true}; });
  }
  Vec3d exact(const Vec3d& v, bool positiveSide) const {
    return rotateAbout(normal, positiveSide ? alpha : -alpha, v);
  }
  // The direction at fractional texel coordinates (s, t) of the face (texel centres at i + 0.5):
  // texel centre directions lie on the face's plane, affine in the index.
  Vec3d at(double s, double t) const {
    const int i = static_cast<int>(std::floor(s - 0.5)), j = static_cast<int>(std::floor(t - 0.5));
    const double fs = s - 0.5 - i, ft = t - 0.5 - j;
    const Vec3d a = (1 - fs) * texelDirection(face, i, j, n) + fs * texelDirection(face, i + 1, j, n);
    const Vec3d b = (1 - fs) * texelDirection(face, i, j + 1, n) + fs * texelDirection(face, i + 1, j + 1, n);
    return normalized((1 - ft) * a + ft * b);
  }
};

TEST(CutAwareLookup, KeepsEachSideOfAJumpAndExtrapolatesItAcross) {
  const ShearedHalves m;
  const double texel = texelAngle(m.n), jump = detail::jumpChord(m.n);
  double worstNear = 0, worstFar = 0, bestPlain = 1e9;
  int straddling = 0;
  // Points from a texel left of the cut to a texel right of it, at several rows.
  for (double s = m.n / 2 - 1.0; s <= m.n / 2 + 1.0; s += 0.0625) {
    if (std::abs(s - m.n / 2) < 1e-9) continue;  // on the cut itself
    for (double t : {20.3, 31.5, 32.0, 40.85}) {
      const Vec3d v = m.at(s, t);
      const bool positive = dot(m.normal, v) > 0;
      ASSERT_EQ(positive, s > m.n / 2);
      const auto near = detail::sampleOneSide(m.map, v, 0, jump);
      ASSERT_TRUE(near);
      worstNear = std::max(worstNear, angleBetween(near->direction, m.exact(v, positive)) / texel);
      EXPECT_EQ(near->alpha, 1.0f);
      const std::array<float, 4> plain = sampleBilinear(m.map, v);
      const Vec3d plainDir = normalized(Vec3d{plain[0], plain[1], plain[2]});
      if (!near->straddles) {
        EXPECT_LT(angleBetween(near->direction, plainDir), 1e-6);  // the plain lookup then
        EXPECT_FALSE(detail::sampleOneSide(m.map, v, 1, jump));
        continue;
      }
      // Strictly within half a texel of the cut the plain blend weighs in the other side.
      if (std::abs(s - m.n / 2) < 0.5) {
        ++straddling;
        bestPlain = std::min(bestPlain, angleBetween(plainDir, m.exact(v, positive)) / texel);
      }
      // The other side, continued across the cut to v.
      const auto far = detail::sampleOneSide(m.map, v, 1, jump);
      ASSERT_TRUE(far);
      worstFar = std::max(worstFar, angleBetween(far->direction, m.exact(v, !positive)) / texel);
      // The spread of one side is a texel's, not the jump.
      EXPECT_LT(near->footprintSpread, 2 * texel);
    }
  }
  EXPECT_EQ(straddling, 4 * 14);
  EXPECT_LT(worstNear, 0.01);
  EXPECT_LT(worstFar, 0.01);
  EXPECT_GT(bestPlain, 0.5);  // what the plain blend does there: lands between the sides
}

}  // namespace
}  // namespace confvis
