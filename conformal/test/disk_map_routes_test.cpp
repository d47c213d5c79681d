// The spherical and hyperbolic disk-map routes against closed forms and against the Euclidean
// route: the hemisphere maps by stereographic projection (up to a disk Möbius map), and on
// irregular disks every route gives the same map up to Möbius, ever closer under refinement.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "confvis/base/error.hpp"
#include "confvis/conformal/disk_map.hpp"
#include "confvis/conformal/distortion.hpp"
#include "confvis/conformal/mesh_generators.hpp"
#include "disk_map_test_support.hpp"

using namespace confvis;
using namespace confvis::conformal;
using Complex = std::complex<double>;

namespace {

constexpr Geometry kCurvedRoutes[] = {Geometry::Spherical, Geometry::Hyperbolic};

DiskMap mapBy(const TriMesh& mesh, Geometry route) {
  DiskMapOptions options;
  options.geometry = route;
  return computeDiskMap(mesh, options);
}

// Three boundary vertices a third of the boundary apart, counter-clockwise.
std::array<int, 3> boundaryMarkers(const TriMesh& mesh) {
  const std::vector<int> loop = boundaryLoops(mesh).at(0);  // clockwise: boundary half-edges
  const std::size_t n = loop.size();
  return {loop[0], loop[2 * n / 3], loop[n / 3]};
}

// Max distance between two maps after aligning both at the same markers.
double alignedDistance(const TriMesh& mesh, std::vector<Complex> a, std::vector<Complex> b,
                       bool byAzimuth = false) {
  return test::alignedDistance(std::move(a), std::move(b),
                               byAzimuth ? test::azimuthMarkers(mesh) : boundaryMarkers(mesh));
}

void expectValidDiskMap(const TriMesh& mesh, const DiskMap& map, Geometry route) {
  EXPECT_EQ(map.geometry, route);
  EXPECT_LE(map.flow.maxCurvatureError, 1e-10) << toString(route);  // the default tolerance
  const DistortionStats stats = measureDistortion(mesh, map.uv);
  EXPECT_EQ(stats.flippedFaces, 0) << toString(route);
  EXPECT_LT(stats.boundaryRoundness, 1e-8) << toString(route);
  for (const auto& z : map.uv) ASSERT_LE(std::abs(z), 1 + 1e-8) << toString(route);
}

double hemisphereError(int n, Geometry route) {
  const TriMesh mesh = makeHemisphere(n, 0.2, 11);
  const DiskMap map = mapBy(mesh, route);
  expectValidDiskMap(mesh, map, route);
  std::vector<Complex> stereo;
  for (auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    stereo.emplace_back(p[0] / (1 + p[2]), p[1] / (1 + p[2]));  // from the south pole
  }
  return alignedDistance(mesh, map.uv, stereo, true);
}

TEST(DiskMapRoutes, HemisphereConvergesToStereographicProjection) {
  for (Geometry route : kCurvedRoutes) {
    const double e8 = hemisphereError(8, route), e16 = hemisphereError(16, route),
                 e32 = hemisphereError(32, route);
    // Each refinement halves the edge length; the error must shrink, at least linearly. The
    // curved routes need no removed face: measured 2.9e-2, 7.2e-3, 1.1e-3 (spherical) and
    // 5.5e-3, 1.4e-3, 3.9e-4 (hyperbolic), against 3.4e-2, 1.6e-2, 7.0e-3 for the Euclidean.
    EXPECT_LT(e16, 0.6 * e8) << toString(route) << " " << e8 << " " << e16;
    EXPECT_LT(e32, 0.6 * e16) << toString(route) << " " << e16 << " " << e32;
    EXPECT_LT(e32, 3e-3) << toString(route);
    const double rate = std::log2(e16 / e32);
    EXPECT_GT(rate, 0.9) << toString(route) << ": observed convergence rate " << rate;
  }
}

TEST(DiskMapRoutes, AgreeWithTheEuclideanRouteUpToMobiusUnderRefinement) {
  for (Geometry route : kCurvedRoutes) {
    // A jittered round disk: irregular, but with well-shaped triangles.
    double previous = 1;
    for (int n : {8, 16, 32}) {
      const TriMesh mesh = makeRoundDisk(n, 0.2, 3);
      const DiskMap map = mapBy(mesh, route);
      expectValidDiskMap(mesh, map, route);
      const double d = alignedDistance(mesh, map.uv, computeDiskMap(mesh).uv);
      EXPECT_LT(d, previous) << toString(route) << " n " << n;
      previous = d;
    }
    EXPECT_LT(previous, 0.015) << toString(route);
    // A lopsided one (bent, jittered, flips needed). Refined fourfold: with flips the Euclidean
    // map depends on the path the flow took (the Delaunay triangulation reached), by up to 0.02
    // at these sizes (measured n = 8..32, plain and guessed start), not monotone in n.
    const TriMesh coarse = makeLopsidedDisk(8, 0.2, 2), fine = makeLopsidedDisk(32, 0.2, 2);
    const DiskMap coarseMap = mapBy(coarse, route), fineMap = mapBy(fine, route);
    expectValidDiskMap(coarse, coarseMap, route);
    expectValidDiskMap(fine, fineMap, route);
    const double dCoarse = alignedDistance(coarse, coarseMap.uv, computeDiskMap(coarse).uv);
    const double dFine = alignedDistance(fine, fineMap.uv, computeDiskMap(fine).uv);
    EXPECT_LT(dFine, dCoarse) << toString(route);
    EXPECT_LT(dFine, 0.015) << toString(route);
  }
}

// From n = 24 the curved routes stalled near 1e-9 on these meshes (every seed tried): their
// edge lengths went through acosh / acos of values rounded near 1, noise the flow could not get
// below. A lopsided disk needs the spherical continuation too.
TEST(DiskMapRoutes, LopsidedMeshesConvergeToTheTolerance) {
  for (Geometry route : kCurvedRoutes)
    for (std::uint64_t seed : {1u, 3u}) {
      const TriMesh mesh = makeLopsidedDisk(24, 0.2, seed);
      const DiskMap map = mapBy(mesh, route);
      expectValidDiskMap(mesh, map, route);
      // The Euclidean route's removed face costs it accuracy at this size (0.021 at most,
      // measured).
      EXPECT_LT(alignedDistance(mesh, map.uv, computeDiskMap(mesh).uv), 0.03)
          << toString(route) << " seed " << seed;
    }
}

// The hyperbolic route's boundary targets depend on the metric: the error it reports is the
// final metric's against its own inscribed polygon, and must meet the tolerance asked for (it
// used to be a bound, the last flow's error plus the last target change, up to twice that).
TEST(DiskMapRoutes, HyperbolicErrorMeetsTheToleranceAgainstTheFinalBoundary) {
  for (std::uint64_t seed : {3u, 4u}) {
    const TriMesh mesh = makeLopsidedDisk(16, 0.2, seed);
    for (double tolerance : {1e-6, 1e-8, 1e-10}) {
      DiskMapOptions options;
      options.geometry = Geometry::Hyperbolic;
      options.tolerance = tolerance;
      const DiskMap map = computeDiskMap(mesh, options);
      EXPECT_LE(map.flow.maxCurvatureError, tolerance) << "seed " << seed;
      EXPECT_GT(map.flow.maxCurvatureError, 0) << "seed " << seed;
      EXPECT_LT(measureDistortion(mesh, map.uv).boundaryRoundness, std::max(tolerance, 1e-8));
    }
  }
}

TEST(DiskMapRoutes, HyperbolicBoundaryIsIteratedToACircle) {
  const TriMesh mesh = makeLopsidedDisk(12, 0.2, 3);
  const DiskMap map = mapBy(mesh, Geometry::Hyperbolic);
  EXPECT_GT(map.boundaryUpdates, 1);  // the first targets cannot be the final ones
  EXPECT_LT(measureDistortion(mesh, map.uv).boundaryRoundness, 1e-8);
}

TEST(DiskMapRoutes, NonDiskInputIsRejectedByEveryRoute) {
  for (Geometry route : kCurvedRoutes) {
    EXPECT_THROW(mapBy(makeIcosphere(1), route), Error);
    EXPECT_THROW(mapBy(makeDiskWithTwoHoles(8), route), Error);
  }
}

}  // namespace
