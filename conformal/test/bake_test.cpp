// The bake on synthetic display maps with closed forms: identity, rotations, exact coverage,
// the extension past the boundary, bezels, thread independence and input errors.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <random>

#include "bake_test_support.hpp"
#include "confvis/base/error.hpp"
#include "confvis/conformal/bake.hpp"
#include "confvis/conformal/baked_map_quality.hpp"

namespace confvis {
namespace {

using test::makeCapMesh;
constexpr double kPi = std::numbers::pi;

Vec3d texelValue(const CubeMap& map, CubeFace face, int x, int y) {
  const float* p = map.face(face).at(x, y);
  return {p[0], p[1], p[2]};
}
float texelAlpha(const CubeMap& map, CubeFace face, int x, int y) {
  return map.face(face).at(x, y)[3];
}

DisplayMap sameSourceAndTarget(const SphereDiskMesh& mesh) {
  DisplayMap map;
  map.source = mesh;
  map.target = mesh;
  return map;
}

Vec3d randomDirection(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  return normalized(Vec3d{g(rng), g(rng), g(rng)});
}

TEST(Bake, IdenticalSourceAndTargetGiveTheIdentityWithExactCoverage) {
  const int n = 32;
  const SphereDiskMesh cap = makeCapMesh(12, 0.55 * kPi);  // crosses five cube faces
  const RetargetMap map = bakeRetargetMap(sameSourceAndTarget(cap), n);
  ASSERT_EQ(map.resolution(), n);
  int inside = 0, outside = 0;
  for (CubeFace face : kCubeFaces)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const Vec3d d = normalized(texelDirection(face, x, y, n));
        // Coverage is the union of the chord triangles' cones, decided here by brute force;
        // texels within 1e-9 of a triangle edge may go either way.
        const bool covered = test::containingTriangle(cap, d) >= 0;
        if (covered != (test::containingTriangle(cap, d, 1e-9) >= 0)) continue;
        for (const CubeMap* m : {&map.ray, &map.geom}) {
          EXPECT_EQ(texelAlpha(*m, face, x, y), covered ? 1.0f : 0.0f)
              << toString(face) << " " << x << "," << y;
          const Vec3d v = texelValue(*m, face, x, y);
          ASSERT_TRUE(isFinite(v));
          EXPECT_NEAR(norm(v), 1.0, 1e-6);
          if (covered) {
            EXPECT_LT(angleBetween(v, d), 1e-6) << toString(face) << " " << x << "," << y;
          }
        }
        (covered ? inside : outside)++;
      }
  EXPECT_GT(inside, 1000);
  EXPECT_GT(outside, 1000);
}

TEST(Bake, RotatedTargetGivesTheRotationBothWays) {
  // Target = source rotated by R: T_ray = R^-1 on the target, T_geom = R on the source.
  const Vec3d axis = normalized(Vec3d{1, 2, -0.5});
  const double angle = 0.7;
  const SphereDiskMesh source = makeCapMesh(16, 0.8 * kPi);
  SphereDiskMesh target = source;
  for (Vec3d& p : target.sphere) p = test::rotate(p, axis, angle);
  DisplayMap display{source, target};
  const int n = 48;
  const RetargetMap map = bakeRetargetMap(display, n);
  int checkedRay = 0, checkedGeom = 0;
  for (CubeFace face : kCubeFaces)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const Vec3d d = normalized(texelDirection(face, x, y, n));
        if (texelAlpha(map.ray, face, x, y) == 1.0f) {
          EXPECT_LT(angleBetween(texelValue(map.ray, face, x, y), test::rotate(d, axis, -angle)),
                    1e-6);
          ++checkedRay;
        }
        if (texelAlpha(map.geom, face, x, y) == 1.0f) {
          EXPECT_LT(angleBetween(texelValue(map.geom, face, x, y), test::rotate(d, axis, angle)),
                    1e-6);
          ++checkedGeom;
        }
      }
  // The cap covers (1 - cos 0.8 pi) / 2 = 90% of the sphere, less the polygon's rim.
  EXPECT_GT(checkedRay, 0.85 * 6 * n * n);
  EXPECT_GT(checkedGeom, 0.85 * 6 * n * n);
  // Bilinear lookups (RetargetMap's CPU path) at random directions equal those in the analytic
  // rotation map (exact at every texel, the ideal bake: lookups across face edges have their own
  // error, see CubeMapSampling), also next to the boundary thanks to the extension.
  RetargetMap exact = map;
  fillCubeMap(exact.ray, [&](const Vec3d& d) { return std::pair{test::rotate(d, axis, -angle), true}; });
  fillCubeMap(exact.geom, [&](const Vec3d& v) { return std::pair{test::rotate(v, axis, angle), true}; });
  std::mt19937_64 rng(7);
  double worst = 0;
  int compared = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3d v = randomDirection(rng);
    const Vec3d d = test::rotate(v, axis, angle);
    if (test::containingTriangle(source, v) < 0) continue;
    if (const auto looked = map.toPhysical(v)) {
      worst = std::max(worst, angleBetween(*looked, *exact.toPhysical(v)));
      ++compared;
    }
    if (const auto looked = map.toVirtual(d)) {
      worst = std::max(worst, angleBetween(*looked, *exact.toVirtual(d)));
      ++compared;
    }
  }
  EXPECT_GT(compared, 30000);
  EXPECT_LT(worst / texelAngle(n), 0.01);
}

TEST(Bake, ExtensionPastTheBoundaryKeepsBilinearLookupsAccurate) {
  // The identity on a cap: a lookup just inside the rim blends in texels outside it. With the
  // extension these hold the extrapolated identity, so lookups equal those in the exact identity
  // map; a map whose outside texels hold some other direction (here the cap's centre, as an
  // unextended bake might) must do visibly worse.
  const int n = 64;
  const SphereDiskMesh cap = makeCapMesh(24, 0.4 * kPi);
  const RetargetMap map = bakeRetargetMap(sameSourceAndTarget(cap), n);
  const RetargetMap exact = RetargetMap::identity(n);
  RetargetMap unextended = map;
  for (ImageRGBA& face : unextended.ray.faces)
    for (std::size_t i = 0; i < face.pixelCount(); ++i)
      if (face.pixels[4 * i + 3] == 0.0f) {
        face.pixels[4 * i] = face.pixels[4 * i + 1] = 0.0f;
        face.pixels[4 * i + 2] = -1.0f;
      }
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> polar(0.4 * kPi - 0.08, 0.4 * kPi), azimuth(0, 2 * kPi);
  double worstExtended = 0, worstUnextended = 0;
  int nearRim = 0;
  for (int i = 0; i < 3000; ++i) {
    // Within two texels of the rim, inside the polygon (which lies inside the cap's circle).
    const double theta = polar(rng), phi = azimuth(rng);
    const Vec3d d{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), -std::cos(theta)};
    if (test::containingTriangle(cap, d) < 0) continue;
    const auto extended = map.toVirtual(d), plain = unextended.toVirtual(d);
    if (!extended || !plain) continue;
    ++nearRim;
    const Vec3d ideal = *exact.toVirtual(d);
    worstExtended = std::max(worstExtended, angleBetween(*extended, ideal));
    worstUnextended = std::max(worstUnextended, angleBetween(*plain, ideal));
  }
  ASSERT_GT(nearRim, 500);
  EXPECT_LT(worstExtended / texelAngle(n), 0.01);
  EXPECT_GT(worstUnextended / texelAngle(n), 0.2);
  // Every uncovered texel holds a unit direction, far from the cap too.
  for (const ImageRGBA& face : map.ray.faces)
    for (std::size_t i = 0; i < face.pixelCount(); ++i) {
      const Vec3d v{face.pixels[4 * i], face.pixels[4 * i + 1], face.pixels[4 * i + 2]};
      ASSERT_NEAR(norm(v), 1.0, 1e-5);
    }
}

TEST(Bake, UnlitTrianglesAreCoveredButTransparent) {
  SphereDiskMesh cap = makeCapMesh(12, 0.5 * kPi);
  DisplayMap display = sameSourceAndTarget(cap);
  display.target.lit.assign(cap.triangles.size(), 1);
  // Unlight the triangles in the right half (x > 0): a vertical bezel strip.
  for (std::size_t t = 0; t < cap.triangles.size(); ++t) {
    double x = 0;
    for (int v : cap.triangles[t]) x += cap.sphere[v].x;
    if (x > 0) display.target.lit[t] = 0;
  }
  const int n = 32;
  const RetargetMap map = bakeRetargetMap(display, n);
  int unlit = 0;
  for (CubeFace face : kCubeFaces)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const Vec3d d = normalized(texelDirection(face, x, y, n));
        const int t = test::containingTriangle(cap, d);
        if (t < 0 || t != test::containingTriangle(cap, d, 1e-9)) continue;
        const bool lit = display.target.lit[t] != 0;
        // Is d strictly inside triangle t (not on an edge shared with a differently lit one)?
        EXPECT_EQ(texelAlpha(map.ray, face, x, y), lit ? 1.0f : 0.0f);
        EXPECT_EQ(texelAlpha(map.geom, face, x, y), 1.0f);  // every source direction is shown
        EXPECT_LT(angleBetween(texelValue(map.ray, face, x, y), d), 1e-6);  // the map itself
        unlit += !lit;
      }
  EXPECT_GT(unlit, 500);
}

// T_ray at physical direction d by brute force: d's barycentric coordinates in the chord
// triangle of `target` holding it give the disk point z; z's barycentric coordinates in the
// `source` disk triangle holding it give the virtual direction. nullopt where d is not covered
// or z lies near the disks' rims (|z| > 0.95: where the source and target rim polygons differ,
// the bake clamps).
std::optional<Vec3d> bruteForceRay(const SphereDiskMesh& target, const SphereDiskMesh& source,
                                   const Vec3d& d) {
  const int t = test::containingTriangle(target, d);
  if (t < 0) return std::nullopt;
  const auto& tri = target.triangles[t];
  const Vec3d &a = target.sphere[tri[0]], &b = target.sphere[tri[1]], &c = target.sphere[tri[2]];
  const double w[3] = {dot(d, cross(b, c)), dot(d, cross(c, a)), dot(d, cross(a, b))};
  const double sum = w[0] + w[1] + w[2];
  const std::complex<double> z =
      (w[0] * target.disk[tri[0]] + w[1] * target.disk[tri[1]] + w[2] * target.disk[tri[2]]) / sum;
  if (std::abs(z) > 0.95) return std::nullopt;
  for (const auto& s : source.triangles) {
    const std::complex<double> p0 = source.disk[s[0]], e1 = source.disk[s[1]] - p0,
                               e2 = source.disk[s[2]] - p0, q = z - p0;
    const double det = e1.real() * e2.imag() - e1.imag() * e2.real();
    const double l1 = (q.real() * e2.imag() - q.imag() * e2.real()) / det;
    const double l2 = (e1.real() * q.imag() - e1.imag() * q.real()) / det;
    if (std::min({1 - l1 - l2, l1, l2}) < -1e-12) continue;
    return normalized((1 - l1 - l2) * source.sphere[s[0]] + l1 * source.sphere[s[1]] +
                      l2 * source.sphere[s[2]]);
  }
  return std::nullopt;
}

TEST(Bake, WalkAcrossManySourceTrianglesPerTexelMatchesBruteForce) {
  // A coarse target over a fine source of the same cap: between two neighbouring texels the
  // disk point crosses many source triangles (at 4 texels a face more than the walk's 16
  // crossings, so point location takes over). Every texel must equal T_ray by brute force.
  const SphereDiskMesh source = makeCapMesh(64, 0.7 * kPi);
  const SphereDiskMesh target = makeCapMesh(6, 0.7 * kPi);
  for (const int n : {4, 16}) {
    const RetargetMap map = bakeRetargetMap(DisplayMap{source, target}, n);
    int checked = 0;
    for (CubeFace face : kCubeFaces)
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
          const Vec3d d = normalized(texelDirection(face, x, y, n));
          // Texels within 1e-9 of a target edge may go either way.
          if ((test::containingTriangle(target, d) >= 0) !=
              (test::containingTriangle(target, d, 1e-9) >= 0))
            continue;
          const std::optional<Vec3d> expected = bruteForceRay(target, source, d);
          if (!expected) continue;
          ASSERT_EQ(texelAlpha(map.ray, face, x, y), 1.0f) << toString(face) << " " << x << "," << y;
          EXPECT_LT(angleBetween(texelValue(map.ray, face, x, y), *expected), 1e-6)
              << n << " " << toString(face) << " " << x << "," << y;
          ++checked;
        }
    EXPECT_GT(checked, 0.5 * 6 * n * n);
  }
}

TEST(Bake, ThreadCountDoesNotChangeTheResult) {
  const Vec3d axis = normalized(Vec3d{0.3, -1, 0.2});
  const SphereDiskMesh source = makeCapMesh(20, 0.9 * kPi);
  SphereDiskMesh target = makeCapMesh(14, 0.45 * kPi);  // a different mesh: a Möbius map
  for (Vec3d& p : target.sphere) p = test::rotate(p, axis, 0.4);
  DisplayMap display{source, target};
  BakeOptions one, four;
  one.threads = 1;
  four.threads = 4;
  const RetargetMap a = bakeRetargetMap(display, 40, one), b = bakeRetargetMap(display, 40, four);
  for (int f = 0; f < 6; ++f) {
    EXPECT_EQ(a.ray.faces[f].pixels, b.ray.faces[f].pixels) << f;
    EXPECT_EQ(a.geom.faces[f].pixels, b.geom.faces[f].pixels) << f;
  }
}

TEST(Bake, BakingIntoAReusedMapGivesTheFreshResult) {
  // First a bake that covers (alpha 1) texels the second leaves uncovered: a reused map must not
  // keep that alpha, nor any other earlier value.
  const DisplayMap wide = sameSourceAndTarget(makeCapMesh(20, 0.95 * kPi));
  SphereDiskMesh target = makeCapMesh(14, 0.45 * kPi);
  for (Vec3d& p : target.sphere) p = test::rotate(p, normalized(Vec3d{1, 0.5, 0}), 0.7);
  const DisplayMap narrow{makeCapMesh(20, 0.9 * kPi), target};
  RetargetMap reused;
  bakeRetargetMapInto(wide, 32, {}, reused);
  const float* before = reused.ray.faces[0].pixels.data();
  bakeRetargetMapInto(narrow, 32, {}, reused);
  EXPECT_EQ(reused.ray.faces[0].pixels.data(), before);  // the storage was reused
  const RetargetMap fresh = bakeRetargetMap(narrow, 32);
  std::size_t uncovered = 0;
  for (int f = 0; f < 6; ++f) {
    EXPECT_EQ(reused.ray.faces[f].pixels, fresh.ray.faces[f].pixels) << f;
    EXPECT_EQ(reused.geom.faces[f].pixels, fresh.geom.faces[f].pixels) << f;
    for (std::size_t i = 3; i < fresh.ray.faces[f].pixels.size(); i += 4)
      uncovered += fresh.ray.faces[f].pixels[i] == 0.0f;
  }
  EXPECT_GT(uncovered, 6u * 32 * 32 / 4);  // the narrow cap leaves much of the sphere invalid
}

TEST(Bake, MalformedInputGivesOneClearError) {
  const DisplayMap good = sameSourceAndTarget(makeCapMesh(4, 1.0));
  auto expectError = [](const DisplayMap& map, int resolution, const std::string& fragment) {
    test::expectError([&] { bakeRetargetMap(map, resolution); }, ErrorCode::InvalidInput, fragment);
  };
  expectError(good, 0, "resolution");
  expectError(good, 9000, "resolution");
  DisplayMap bad = good;
  bad.target.triangles[3][1] = 100000;
  expectError(bad, 16, "target mesh: triangle 3");
  bad = good;
  bad.source.sphere[2] = {0, 0, 2};
  expectError(bad, 16, "source mesh: vertex 2");
  bad = good;
  bad.source.disk[5] = {std::nan(""), 0};
  expectError(bad, 16, "source mesh: disk point of vertex 5");
  bad = good;
  bad.target.disk.pop_back();
  expectError(bad, 16, "target mesh");
  bad = good;
  bad.target.lit.assign(2, 1);
  expectError(bad, 16, "lit flags");
  bad = good;
  bad.source.triangles.clear();
  expectError(bad, 16, "source mesh: no triangles");
}

TEST(Bake, VulkanLayoutLookupMatchesToVirtual) {
  // The renderers upload toVulkanLayout(map.ray) and sample it with Vulkan's face table: that
  // lookup must return what RetargetMap::toVirtual returns (here for a rotation map).
  const Vec3d axis = normalized(Vec3d{-1, 0.5, 2});
  const SphereDiskMesh source = makeCapMesh(16, 0.85 * kPi);
  SphereDiskMesh target = source;
  for (Vec3d& p : target.sphere) p = test::rotate(p, axis, 1.1);
  const int n = 32;
  const RetargetMap map = bakeRetargetMap(DisplayMap{source, target}, n);
  const CubeMap vulkan = toVulkanLayout(map.ray);
  std::mt19937_64 rng(11);
  int compared = 0;
  for (int i = 0; i < 5000; ++i) {
    const Vec3d d = randomDirection(rng);
    CubeFace face;
    double x, y;
    vulkanDirectionToTexel(d, n, face, x, y);
    const int ix = std::clamp(static_cast<int>(x), 0, n - 1), iy = std::clamp(static_cast<int>(y), 0, n - 1);
    const float* viaVulkan = vulkan.face(face).at(ix, iy);
    const std::array<float, 4> viaExr = sampleNearest(map.ray, d);
    for (int c = 0; c < 4; ++c) ASSERT_EQ(viaVulkan[c], viaExr[c]) << i;
    // Bilinear inside the face (Vulkan's hardware filter): the same as toVirtual.
    const double fx = x - 0.5, fy = y - 0.5;
    if (fx < 0 || fy < 0 || fx >= n - 1 || fy >= n - 1) continue;
    const int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy);
    const double tx = fx - x0, ty = fy - y0;
    double s[4] = {0, 0, 0, 0};
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) {
        const float* t = vulkan.face(face).at(x0 + k, y0 + j);
        const double w = (k ? tx : 1 - tx) * (j ? ty : 1 - ty);
        for (int c = 0; c < 4; ++c) s[c] += w * t[c];
      }
    const std::optional<Vec3d> expected = map.toVirtual(d);
    ASSERT_EQ(expected.has_value(), s[3] >= 0.5) << i;
    if (!expected) continue;
    EXPECT_LT(angleBetween(normalized(Vec3d{s[0], s[1], s[2]}), *expected), 1e-6) << i;
    ++compared;
  }
  EXPECT_GT(compared, 2000);
}

}  // namespace
}  // namespace confvis
