// Per-vertex Möbius blending (map_interpolation.hpp): exact for Möbius maps, far more accurate
// and smoother than linear interpolation on a smooth conformal map, continuous across edges, and
// what the bake writes is what DisplayMapEvaluator evaluates.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "../src/disk_locator.hpp"
#include "../src/smooth_interpolation.hpp"
#include "bake_test_support.hpp"
#include "confvis/base/cube_map.hpp"
#include "confvis/conformal/bake.hpp"
#include "confvis/conformal/map_accuracy.hpp"

namespace confvis {
namespace {

using Complex = std::complex<double>;
constexpr double kDegree = std::numbers::pi / 180;

// makeCapMesh(n, pi/2)'s disk coordinate of a direction of the front hemisphere (-z): the
// stereographic projection from +z (the cap mesh's closed form).
Complex stereographic(const Vec3d& x) { return Complex(x.x, x.y) / (1.0 - x.z); }

// A disk automorphism (a Möbius map): e^{i 0.4} (z - a) / (1 - conj(a) z).
Complex diskMobius(Complex z) {
  const Complex a(0.3, -0.2);
  return std::polar(1.0, 0.4) * (z - a) / (1.0 - std::conj(a) * z);
}

// A conformal map of the closed unit disk that is no Möbius map (f' = 1 + 0.5 z != 0).
Complex smoothConformal(Complex z) { return z + 0.25 * z * z; }

// The hemisphere cap mesh with its disk points replaced by map(stereographic).
SphereDiskMesh hemisphere(int n, Complex (*map)(Complex)) {
  SphereDiskMesh mesh = test::makeCapMesh(n, std::numbers::pi / 2);
  for (std::size_t v = 0; v < mesh.sphere.size(); ++v)
    mesh.disk[v] = map(stereographic(mesh.sphere[v]));
  return mesh;
}

// The chord-triangle barycentric coordinates of direction x in triangle t (triple products).
std::array<double, 3> chordBarycentric(const SphereDiskMesh& mesh, int t, const Vec3d& x) {
  const auto& c = mesh.triangles[t];
  const Vec3d &a = mesh.sphere[c[0]], &b = mesh.sphere[c[1]], &d = mesh.sphere[c[2]];
  std::array<double, 3> w{dot(x, cross(b, d)), dot(x, cross(d, a)), dot(x, cross(a, b))};
  const double sum = w[0] + w[1] + w[2];
  for (double& value : w) value /= sum;
  return w;
}

Vec3d pointIn(const SphereDiskMesh& mesh, int t, const std::array<double, 3>& b) {
  const auto& c = mesh.triangles[t];
  return normalized(b[0] * mesh.sphere[c[0]] + b[1] * mesh.sphere[c[1]] + b[2] * mesh.sphere[c[2]]);
}

Complex linearDisk(const SphereDiskMesh& mesh, int t, const std::array<double, 3>& b) {
  const auto& c = mesh.triangles[t];
  return b[0] * mesh.disk[c[0]] + b[1] * mesh.disk[c[1]] + b[2] * mesh.disk[c[2]];
}

std::array<double, 3> randomBarycentric(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  double u = uni(rng), v = uni(rng);
  if (u + v > 1) u = 1 - u, v = 1 - v;
  return {1 - u - v, u, v};
}

// Interior edges: (triangle, corner opposite the edge, neighbour triangle).
struct SharedEdge {
  int t1, t2, i, j;  // the edge's vertices i, j
};
std::vector<SharedEdge> sharedEdges(const SphereDiskMesh& mesh) {
  std::map<std::pair<int, int>, int> seen;
  std::vector<SharedEdge> out;
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t)
    for (int k = 0; k < 3; ++k) {
      const int i = mesh.triangles[t][k], j = mesh.triangles[t][(k + 1) % 3];
      const auto key = std::minmax(i, j);
      const auto it = seen.find(key);
      if (it == seen.end()) seen[key] = t;
      else out.push_back({it->second, t, i, j});
    }
  return out;
}

std::array<double, 3> edgeBarycentric(const SphereDiskMesh& mesh, int t, int i, int j,
                                      double tau) {
  std::array<double, 3> b{0, 0, 0};
  for (int k = 0; k < 3; ++k) {
    if (mesh.triangles[t][k] == i) b[k] = 1 - tau;
    if (mesh.triangles[t][k] == j) b[k] = tau;
  }
  return b;
}

TEST(MobiusBlend, ReproducesAMobiusMapExactlyBothWays) {
  const SphereDiskMesh mesh = hemisphere(10, diskMobius);
  const detail::MobiusBlend blend(mesh);
  const detail::DiskLocator locator(mesh.disk, mesh.triangles);
  std::mt19937_64 rng(3);
  double forward = 0, backward = 0, linear = 0;
  int hint = -1, inverted = 0;
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t)
    for (int sample = 0; sample < 4; ++sample) {
      const std::array<double, 3> b = randomBarycentric(rng);
      const Vec3d x = pointIn(mesh, t, b);
      const Complex exact = diskMobius(stereographic(x));
      forward = std::max(forward, std::abs(blend.toDisk(t, b, x) - exact));
      linear = std::max(linear, std::abs(linearDisk(mesh, t, b) - exact));
      const detail::DiskLocator::Hit hit = locator.locate(exact, hint);
      if (!hit.inside) continue;  // between a rim chord and the unit circle
      ++inverted;
      const Vec3d back = normalized(blend.toSphere(hit.triangle, hit.barycentric, exact));
      backward = std::max(backward, norm(back - x));
    }
  EXPECT_GT(inverted, 300);
  EXPECT_LT(forward, 1e-12);
  EXPECT_LT(backward, 1e-12);
  EXPECT_GT(linear, 1e-4);  // the linear interpolation is not exact: the test can fail
}

TEST(MobiusBlend, IsFarMoreAccurateThanLinearOnASmoothConformalMap) {
  // Hemisphere, disk points from the closed form f(stereographic) at the vertices; error against
  // the closed form inside the triangles. The smooth interpolation's error falls as h^3, the
  // linear one's as h^2: at 10 and 20 rings, 50x and 100x apart.
  for (const int rings : {10, 20}) {
    const SphereDiskMesh mesh = hemisphere(rings, smoothConformal);
    const detail::MobiusBlend blend(mesh);
    std::mt19937_64 rng(7);
    double smooth = 0, linear = 0;
    for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t)
      for (int sample = 0; sample < 3; ++sample) {
        const std::array<double, 3> b = randomBarycentric(rng);
        const Vec3d x = pointIn(mesh, t, b);
        const Complex exact = smoothConformal(stereographic(x));
        smooth = std::max(smooth, std::abs(blend.toDisk(t, b, x) - exact));
        linear = std::max(linear, std::abs(linearDisk(mesh, t, b) - exact));
      }
    RecordProperty("rings" + std::to_string(rings) + "_ratio", std::to_string(linear / smooth));
    EXPECT_LT(smooth * (rings == 10 ? 50 : 100), linear) << rings << " rings: smooth " << smooth
                                                          << ", linear " << linear;
  }
}

// The turn (degrees) of the image of the sphere's great circle through the edge point m along
// tangent d, at m, with the map F evaluated in t1 before and in t2 after the crossing.
template <class Map>
double turnAcross(const SphereDiskMesh& mesh, const SharedEdge& e, double tau, const Map& map) {
  const Vec3d m = pointIn(mesh, e.t1, edgeBarycentric(mesh, e.t1, e.i, e.j, tau));
  auto centroid = [&](int t) {
    return pointIn(mesh, t, {1.0 / 3, 1.0 / 3, 1.0 / 3});
  };
  // Across the edge, perpendicular to it, from t1 into t2.
  Vec3d d = normalized(cross(m, mesh.sphere[e.j] - mesh.sphere[e.i]));
  if (dot(d, centroid(e.t2) - centroid(e.t1)) < 0) d = -1.0 * d;
  const double eps = 1e-6;
  auto at = [&](int t, double s) {
    const Vec3d x = normalized(m + s * d);
    return map(t, chordBarycentric(mesh, t, x), x);
  };
  const Complex before = at(e.t1, 0) - at(e.t1, -eps), after = at(e.t2, eps) - at(e.t2, 0);
  return std::abs(std::arg(after / before)) / kDegree;
}

TEST(MobiusBlend, StraightLinesTurnBelowAQuarterDegreeWhereLinearKinks) {
  const SphereDiskMesh mesh = hemisphere(24, smoothConformal);
  const detail::MobiusBlend blend(mesh);
  std::vector<double> smooth, linear;
  for (const SharedEdge& e : sharedEdges(mesh)) {
    // The cap mesh's rim triangles are clamped from a square grid (slivers, folds): inside only.
    if (std::abs(stereographic(mesh.sphere[e.i])) > 0.9 ||
        std::abs(stereographic(mesh.sphere[e.j])) > 0.9)
      continue;
    smooth.push_back(turnAcross(mesh, e, 0.4, [&](int t, const std::array<double, 3>& b,
                                                  const Vec3d& x) { return blend.toDisk(t, b, x); }));
    linear.push_back(turnAcross(mesh, e, 0.4, [&](int t, const std::array<double, 3>& b,
                                                  const Vec3d&) { return linearDisk(mesh, t, b); }));
  }
  std::sort(smooth.begin(), smooth.end());
  std::sort(linear.begin(), linear.end());
  ASSERT_GT(smooth.size(), 100u);
  const std::size_t p99 = smooth.size() * 99 / 100;
  EXPECT_LT(smooth[p99], 0.25) << "max " << smooth.back() << ", linear p99 " << linear[p99];
  EXPECT_GT(linear[p99], 0.25) << "smooth p99 " << smooth[p99];
  EXPECT_GT(linear[smooth.size() / 2], 5 * smooth[smooth.size() / 2]);
}

TEST(MobiusBlend, IsContinuousAcrossSharedEdgesBothWays) {
  const SphereDiskMesh mesh = hemisphere(8, smoothConformal);
  const detail::MobiusBlend blend(mesh);
  double sphereGap = 0, diskGap = 0;
  for (const SharedEdge& e : sharedEdges(mesh))
    for (const double tau : {0.1, 0.35, 0.5, 0.8}) {
      const auto b1 = edgeBarycentric(mesh, e.t1, e.i, e.j, tau);
      const auto b2 = edgeBarycentric(mesh, e.t2, e.i, e.j, tau);
      const Vec3d x = pointIn(mesh, e.t1, b1);
      sphereGap = std::max(sphereGap, std::abs(blend.toDisk(e.t1, b1, x) - blend.toDisk(e.t2, b2, x)));
      const Complex z = (1 - tau) * mesh.disk[e.i] + tau * mesh.disk[e.j];
      diskGap = std::max(diskGap, norm(blend.toSphere(e.t1, b1, z) - blend.toSphere(e.t2, b2, z)));
    }
  EXPECT_LT(sphereGap, 1e-14);
  EXPECT_LT(diskGap, 1e-14);
  // At a vertex the map is the vertex's disk point.
  for (int v = 0; v < static_cast<int>(mesh.sphere.size()); ++v) {
    EXPECT_NEAR(std::abs(blend.chart(v).z0 - mesh.disk[v]), 0.0, 0.0);
  }
}

TEST(MobiusBlend, TheBakeWritesWhatTheEvaluatorComputes) {
  // A map between two caps: the source cap turned by 20 degrees against the target, so T_ray
  // is a rotation composed with interpolation.
  DisplayMap map;
  map.target = test::makeCapMesh(10, 1.0);
  map.source = test::makeCapMesh(12, 1.1, [](const Vec3d& s) {
    return test::rotate(Vec3d{s.x, -s.y, -s.z}, normalized(Vec3d{1, 2, 0}), 0.2);
  });
  const int n = 48;
  BakeOptions options;
  options.interpolation = MapInterpolation::Mobius;
  const RetargetMap baked = bakeRetargetMap(map, n, options);
  BakeOptions linearOptions;
  linearOptions.interpolation = MapInterpolation::Linear;
  const RetargetMap bakedLinear = bakeRetargetMap(map, n, linearOptions);
  const DisplayMapEvaluator eval(map, MapInterpolation::Mobius);
  int checked = 0;
  double worst = 0, linearDifference = 0;
  for (const CubeFace face : kCubeFaces)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const float* texel = baked.ray.face(face).at(x, y);
        const auto image = eval.toVirtual(normalized(texelDirection(face, x, y, n)));
        if (texel[3] == 0 || !image) continue;
        const Vec3d got{texel[0], texel[1], texel[2]};
        worst = std::max(worst, norm(got - image->direction));
        const float* lin = bakedLinear.ray.face(face).at(x, y);
        linearDifference = std::max(linearDifference, norm(got - Vec3d{lin[0], lin[1], lin[2]}));
        ++checked;
      }
  EXPECT_GT(checked, 500);
  EXPECT_LT(worst, 1e-6);  // float texels
  EXPECT_GT(linearDifference, 1e-5);  // the option reaches the bake
}

}  // namespace
}  // namespace confvis
