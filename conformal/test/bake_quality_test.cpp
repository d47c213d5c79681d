// The baked-map measurements (conformality, orientation, round trip, coverage) on synthetic maps
// with closed forms, including maps they must flag: an anisotropic stretch, a mirror, a bake of
// a non-conformal mesh map.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "bake_test_support.hpp"
#include "confvis/conformal/bake.hpp"
#include "confvis/conformal/baked_map_quality.hpp"

namespace confvis {
namespace {

using test::makeCapMesh;
constexpr double kPi = std::numbers::pi;
constexpr double kTargetCap = 0.4 * kPi, kSourceCap = 0.6 * kPi;

// The display sees the directions within 72 degrees of the front (-z) and shows those within
// 108 degrees. With both disk maps the scaled stereographic projection, T_ray is the Möbius map
// of the sphere that keeps the azimuth and scales tan(theta / 2) by k = tan(54) / tan(36): a
// conformal map in closed form. (Larger caps work the same; the synthetic meshes' own disk maps
// are then further from conformal, see test::diskMapRatios.)
DisplayMap capToCap(int meshN) {
  DisplayMap map;
  map.source = makeCapMesh(meshN, kSourceCap);
  map.target = makeCapMesh(meshN, kTargetCap);
  return map;
}

Vec3d closedFormRay(const Vec3d& d) {
  const double k = std::tan(kSourceCap / 2) / std::tan(kTargetCap / 2);
  const double theta = std::acos(std::clamp(-d.z, -1.0, 1.0));  // from the cap centre, -z
  const double thetaV = 2 * std::atan(k * std::tan(theta / 2));
  const double rho = std::hypot(d.x, d.y);
  if (rho == 0) return {0, 0, -1};
  return {std::sin(thetaV) * d.x / rho, std::sin(thetaV) * d.y / rho, -std::cos(thetaV)};
}

// Largest angle between the baked ray map and the closed form over texels whose direction lies
// within `maxTheta` of the display's centre.
double worstClosedFormError(const RetargetMap& map, double maxTheta) {
  const int n = map.resolution();
  double worst = 0;
  for (CubeFace face : kCubeFaces)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const Vec3d d = normalized(texelDirection(face, x, y, n));
        if (std::acos(std::clamp(-d.z, -1.0, 1.0)) > maxTheta) continue;
        const float* p = map.ray.face(face).at(x, y);
        worst = std::max(worst, angleBetween(Vec3d{p[0], p[1], p[2]}, closedFormRay(d)));
      }
  return worst;
}

TEST(BakedMapQuality, ConformalCapMapMatchesItsClosedFormAndConverges) {
  const int n = 64;
  const RetargetMap coarse = bakeRetargetMap(capToCap(12), n);
  const RetargetMap fine = bakeRetargetMap(capToCap(24), n);
  // Piecewise-linear maps converge quadratically in the mesh spacing (here halved).
  const double coarseError = worstClosedFormError(coarse, kTargetCap - 0.05);
  const double fineError = worstClosedFormError(fine, kTargetCap - 0.05);
  EXPECT_LT(fineError, coarseError / 3) << coarseError << " " << fineError;
  EXPECT_LT(fineError, 0.005);  // radians
}

TEST(BakedMapQuality, ConformalCapMapIsConformalOrientedInvertibleAndCovering) {
  const int n = 64;
  const DisplayMap display = capToCap(48);
  const RetargetMap map = bakeRetargetMap(display, n);
  // A baked texel composes one target and one source triangle's affine maps, so its ratio is
  // at most the product of theirs (plus finite-difference error).
  const auto sourceRatios = test::diskMapRatios(display.source);
  const auto targetRatios = test::diskMapRatios(display.target);
  const double bound = *std::max_element(sourceRatios.begin(), sourceRatios.end()) *
                       *std::max_element(targetRatios.begin(), targetRatios.end());
  const BakedConformality ray = measureBakedConformality(map.ray);
  EXPECT_GT(ray.measured, 8000u);
  EXPECT_EQ(ray.flipped, 0u);
  EXPECT_LT(ray.discontinuous, ray.measured / 100);
  EXPECT_LT(ray.ratioP50, 1.06);
  EXPECT_LT(ray.ratioP95, 1.12);
  EXPECT_LT(ray.ratioMax, 1.05 * bound);
  const BakedConformality geom = measureBakedConformality(map.geom);
  EXPECT_GT(geom.measured, 14000u);
  EXPECT_EQ(geom.flipped, 0u);
  EXPECT_LT(geom.ratioP95, 1.12);
  EXPECT_LT(geom.ratioMax, 1.05 * bound);

  // ray and geom are inverses: the round trip through the other map's bilinear lookup.
  const RoundTripStats forth = measureRoundTrip(map, RoundTrip::RayThenGeom);
  const RoundTripStats back = measureRoundTrip(map, RoundTrip::GeomThenRay);
  EXPECT_GT(forth.all.measured, 8500u);
  EXPECT_EQ(forth.all.acrossCut + back.all.acrossCut, 0u);
  // Lookups within half a texel of the other map's rim read alpha < 0.5: a thin band only, and
  // all of it in the boundary part.
  EXPECT_LT(forth.all.invalid, forth.all.measured / 50);
  EXPECT_LT(back.all.invalid, back.all.measured / 50);
  EXPECT_EQ(forth.interior.invalid + back.interior.invalid, 0u);
  EXPECT_LT(forth.all.max, 1.0);
  EXPECT_LT(back.all.max, 1.0);

  const CoverageStats coverage = measureCoverage(map);
  EXPECT_GT(coverage.sourceTexels, 0.6 * 6 * n * n);
  EXPECT_GT(coverage.fraction, 0.99);
}

TEST(BakedMapQuality, FlagsAnAnisotropicStretch) {
  const int n = 48;
  RetargetMap stretch = RetargetMap::identity(n);
  // Doubling x then renormalising: singular-value ratio 2 at +-z, 1 at +-x.
  fillCubeMap(stretch.ray, [](const Vec3d& d) {
    return std::pair{normalized(Vec3d{2 * d.x, d.y, d.z}), true};
  });
  const BakedConformality measured = measureBakedConformality(stretch.ray);
  EXPECT_EQ(measured.flipped, 0u);
  EXPECT_GT(measured.ratioP95, 1.8);
  EXPECT_LT(measured.ratioP95, 2.05);
  const BakedConformality identity = measureBakedConformality(RetargetMap::identity(n).ray);
  EXPECT_LT(identity.ratioMax, 1.01);
  EXPECT_EQ(identity.measured, 6u * n * n);
}

TEST(BakedMapQuality, FlagsAMirror) {
  RetargetMap mirror = RetargetMap::identity(32);
  fillCubeMap(mirror.ray, [](const Vec3d& d) { return std::pair{Vec3d{-d.x, d.y, d.z}, true}; });
  const BakedConformality measured = measureBakedConformality(mirror.ray);
  EXPECT_EQ(measured.flipped, measured.measured);
  EXPECT_LT(measured.ratioMax, 1.01);  // a mirror is anti-conformal: angles kept, orientation not
}

TEST(BakedMapQuality, FlagsABakedNonConformalMeshMap) {
  // Same disk coordinates, target vertices squeezed sideways on the sphere: T_ray undoes the
  // squeeze, a piecewise-linear map with singular-value ratio up to about 2.
  DisplayMap squeezed = capToCap(24);
  squeezed.source = makeCapMesh(24, kTargetCap);
  squeezed.target = makeCapMesh(24, kTargetCap, [](const Vec3d& s) {
    return normalized(Vec3d{0.5 * s.x, -s.y, -s.z});
  });
  const RetargetMap map = bakeRetargetMap(squeezed, 64);
  const BakedConformality measured = measureBakedConformality(map.ray);
  EXPECT_EQ(measured.flipped, 0u);
  EXPECT_GT(measured.ratioP50, 1.3);
  // The same mesh without the squeeze is the identity: ratio 1.
  const BakedConformality identity =
      measureBakedConformality(bakeRetargetMap(DisplayMap{squeezed.source, squeezed.source}, 64).ray);
  EXPECT_LT(identity.ratioMax, 1.01);
}

TEST(BakedMapQuality, CoverageFlagsAnImageThatMissesPartOfTheSource) {
  // ray folds the back hemisphere onto the front one, so its image is the front hemisphere only:
  // the back half of the source is not covered, whatever geom claims.
  RetargetMap folded = RetargetMap::identity(32);
  fillCubeMap(folded.ray, [](const Vec3d& d) {
    return std::pair{Vec3d{d.x, d.y, -std::abs(d.z)}, true};
  });
  const CoverageStats coverage = measureCoverage(folded);
  EXPECT_EQ(coverage.sourceTexels, 6u * 32 * 32);
  EXPECT_NEAR(coverage.fraction, 0.5, 0.05);
  EXPECT_NEAR(measureCoverage(RetargetMap::identity(32)).fraction, 1.0, 1e-12);
}

TEST(BakedMapQuality, SkipsTheJumpAcrossACut) {
  // A map that is continuous except across the plane x = 0, where it jumps by 90 degrees (like
  // geom across the source cut): the texels next to the jump are reported, not measured.
  RetargetMap cut = RetargetMap::identity(32);
  fillCubeMap(cut.geom, [](const Vec3d& d) {
    return std::pair{d.x > 0 ? d : Vec3d{-d.z, d.y, d.x}, true};
  });
  const BakedConformality measured = measureBakedConformality(cut.geom);
  EXPECT_GE(measured.discontinuous, 4u * 2 * 30);  // both sides of the jump on four faces
  // Where the jump shrinks to nothing (at +-y) a texel can look smooth but straddle two
  // different Jacobians: only those few escape, so p99 is clean, the max is not.
  EXPECT_LT(measured.ratioP99, 1.01);
  EXPECT_EQ(measured.flipped, 0u);
}

}  // namespace
}  // namespace confvis
