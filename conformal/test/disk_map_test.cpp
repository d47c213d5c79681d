// The Riemann map against closed forms: a hemisphere maps by stereographic projection (up to a
// disk Möbius map), a round flat disk maps to itself; irregular meshes give no flipped faces.
#include "confvis/conformal/disk_map.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "confvis/base/error.hpp"
#include "confvis/conformal/distortion.hpp"
#include "confvis/conformal/intrinsic_triangulation.hpp"
#include "confvis/conformal/mesh_generators.hpp"
#include "confvis/conformal/mobius.hpp"
#include "disk_map_test_support.hpp"

using namespace confvis;
using namespace confvis::conformal;
using Complex = std::complex<double>;

namespace {

// Max distance between the computed map and a reference, both aligned at the same markers.
double alignedError(const TriMesh& mesh, std::vector<Complex> uv, std::vector<Complex> reference) {
  return test::alignedDistance(std::move(uv), std::move(reference), test::azimuthMarkers(mesh));
}

double hemisphereError(int n) {
  const TriMesh mesh = makeHemisphere(n, 0.2, 11);
  const DiskMap map = computeDiskMap(mesh);
  std::vector<Complex> stereo;
  for (auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    stereo.emplace_back(p[0] / (1 + p[2]), p[1] / (1 + p[2]));  // from the south pole
  }
  return alignedError(mesh, map.uv, stereo);
}

TEST(DiskMap, HemisphereConvergesToStereographicProjection) {
  const double e8 = hemisphereError(8), e16 = hemisphereError(16), e32 = hemisphereError(32);
  // Each refinement halves the edge length; the error must shrink, at least linearly.
  EXPECT_LT(e16, 0.6 * e8) << e8 << " " << e16;
  EXPECT_LT(e32, 0.6 * e16) << e16 << " " << e32;
  EXPECT_LT(e32, 0.02);
  const double rate = std::log2(e16 / e32);
  EXPECT_GT(rate, 0.9) << "observed convergence rate " << rate;
  RecordProperty("hemisphere_error_n32", std::to_string(e32));
  RecordProperty("hemisphere_rate", std::to_string(rate));
}

TEST(DiskMap, RoundFlatDiskMapsToItself) {
  const TriMesh mesh = makeRoundDisk(24, 0.2, 4);
  const DiskMap map = computeDiskMap(mesh);
  std::vector<Complex> identity;
  for (auto v : mesh.vertices()) identity.emplace_back(mesh.point(v)[0], mesh.point(v)[1]);
  // The discrete map of a polygonal disk differs from the identity by the polygon's corners.
  EXPECT_LT(alignedError(mesh, map.uv, identity), 0.02);
}

TEST(DiskMap, OutputIsInTheUnitDiskWithRoundBoundaryAndPreservesOrientation) {
  const TriMesh mesh = makeLopsidedDisk(20, 0.3, 8);
  const DiskMap map = computeDiskMap(mesh);
  const DistortionStats stats = measureDistortion(mesh, map.uv);
  EXPECT_EQ(stats.flippedFaces, 0);
  EXPECT_LT(stats.boundaryRoundness, 1e-8);
  for (const auto& z : map.uv) EXPECT_LE(std::abs(z), 1 + 1e-8);
  EXPECT_LE(map.flow.maxCurvatureError, 1e-10);
  // Angles are preserved on a good mesh (on the sliver-ridden one above the flow needs flips,
  // so the input's own triangles are not those of the conformal metric).
  const TriMesh good = makeRoundDisk(20, 0.1, 8);
  const DistortionStats quality = measureDistortion(good, computeDiskMap(good).uv);
  EXPECT_LT(quality.logAngleRatioStd, 0.05);
  EXPECT_LT(quality.ratioP50, 1.05);
  EXPECT_LT(quality.ratioP99, 1.3);
}

TEST(DiskMap, IrregularMeshesNeverFlipFacesForAnyRobustScheme) {
  for (Scheme scheme : {Scheme::InversiveDistance, Scheme::Yamabe}) {
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      const TriMesh mesh = makeLopsidedDisk(16, 0.2, seed);
      DiskMapOptions options;
      options.scheme = scheme;
      const DiskMap map = computeDiskMap(mesh, options);
      EXPECT_EQ(measureDistortion(mesh, map.uv).flippedFaces, 0)
          << toString(scheme) << " seed " << seed;
    }
  }
}

TEST(DiskMap, SliversAndSharpCornersConvergeWithoutFlippedFaces) {
  // Meshes that made the flow stall or crawl: slivers at the rim of a jittered round disk
  // (inversive distance), single-triangle corners of lopsided disks (tangential and Thurston:
  // power-Delaunay flips never open such a corner for them).
  struct Case {
    TriMesh mesh;
    Scheme scheme;
  };
  const Case cases[] = {{makeRoundDisk(39, 0.2, 42), Scheme::InversiveDistance},
                        {makeLopsidedDisk(39, 0.2, 1), Scheme::Tangential},
                        {makeLopsidedDisk(39, 0.2, 1), Scheme::Thurston},
                        {makeLopsidedDisk(39, 0.2, 3), Scheme::Thurston}};
  for (const Case& c : cases) {
    DiskMapOptions options;
    options.scheme = c.scheme;
    const DiskMap map = computeDiskMap(c.mesh, options);
    EXPECT_LE(map.flow.maxCurvatureError, 1e-10) << toString(c.scheme);
    const DistortionStats stats = measureDistortion(c.mesh, map.uv);
    EXPECT_EQ(stats.flippedFaces, 0) << toString(c.scheme);
    EXPECT_LT(stats.boundaryRoundness, 1e-8) << toString(c.scheme);
  }
}

TEST(DiskMap, NonDiskInputIsRejectedWithItsTopology) {
  try {
    computeDiskMap(makeIcosphere(1));
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("Euler characteristic 2"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("0 boundary loops"), std::string::npos) << e.what();
  }
  EXPECT_THROW(computeDiskMap(makeDiskWithTwoHoles(8)), Error);
  EXPECT_THROW(computeDiskMap(makeGridDisk(1)), Error);  // every face touches the boundary
}

// Points and triangles read off a mesh give the TriMesh route's map bit for bit (the display
// map uses the list route); malformed lists are rejected naming the triangle or vertex.
TEST(DiskMap, TriangleListGivesTheMeshMapAndRejectsMalformedLists) {
  const TriMesh mesh = makeLopsidedDisk(12, 0.2, 3);
  std::vector<Vec3d> points;
  for (auto v : mesh.vertices())
    points.push_back({mesh.point(v)[0], mesh.point(v)[1], mesh.point(v)[2]});
  std::vector<std::array<int, 3>> triangles = meshTriangles(mesh);
  const DiskMap fromMesh = computeDiskMap(mesh);
  const DiskMap fromList = computeDiskMap(points, triangles);
  ASSERT_EQ(fromList.uv.size(), fromMesh.uv.size());
  for (std::size_t v = 0; v < fromMesh.uv.size(); ++v) ASSERT_EQ(fromList.uv[v], fromMesh.uv[v]);
  EXPECT_EQ(fromList.removedFace, fromMesh.removedFace);
  for (Geometry route : {Geometry::Spherical, Geometry::Hyperbolic}) {  // the curved routes too
    DiskMapOptions options;
    options.geometry = route;
    const DiskMap curvedMesh = computeDiskMap(mesh, options);
    const DiskMap curvedList = computeDiskMap(points, triangles, options);
    EXPECT_EQ(curvedList.geometry, route);
    EXPECT_EQ(curvedList.flow.iterations, curvedMesh.flow.iterations) << toString(route);
    ASSERT_EQ(curvedList.uv.size(), curvedMesh.uv.size());
    for (std::size_t v = 0; v < curvedMesh.uv.size(); ++v)
      ASSERT_EQ(curvedList.uv[v], curvedMesh.uv[v]) << toString(route);
  }

  auto rejection = [&](const std::vector<std::array<int, 3>>& list) {
    try {
      computeDiskMap(points, list);
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::InvalidInput) << e.what();
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  auto flipped = triangles;
  std::swap(flipped[5][1], flipped[5][2]);
  EXPECT_NE(rejection(flipped).find("orientations differ"), std::string::npos);
  auto third = triangles;  // a third triangle on the first triangle's first edge
  third.push_back({third[0][2], third[0][1], static_cast<int>(points.size()) - 1});
  EXPECT_NE(rejection(third).find("two other triangles"), std::string::npos);
  auto outOfRange = triangles;
  outOfRange[7][0] = static_cast<int>(points.size());
  EXPECT_NE(rejection(outOfRange).find("triangle 7 refers to vertex"), std::string::npos);
  // Two copies of the disk sharing one boundary vertex: one component and Euler
  // characteristic 1, but not a disk at that vertex.
  int shared = 0;
  for (auto v : mesh.vertices())
    if (mesh.is_boundary(v)) shared = v.idx();
  auto bowtie = triangles;
  const int n = static_cast<int>(points.size());
  for (const auto& t : triangles) {
    std::array<int, 3> copy;
    for (int c = 0; c < 3; ++c) copy[c] = t[c] == shared ? shared : t[c] + n;
    bowtie.push_back(copy);
  }
  std::vector<Vec3d> twice = points;
  twice.insert(twice.end(), points.begin(), points.end());
  try {
    computeDiskMap(twice, bowtie);
    ADD_FAILURE() << "bowtie accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("vertex " + std::to_string(shared)), std::string::npos)
        << e.what();
  }
  const TriMesh sphere = makeIcosphere(1);
  std::vector<Vec3d> spherePoints;
  for (auto v : sphere.vertices())
    spherePoints.push_back({sphere.point(v)[0], sphere.point(v)[1], sphere.point(v)[2]});
  try {
    computeDiskMap(spherePoints, meshTriangles(sphere));
    ADD_FAILURE() << "sphere accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("0 boundary loops"), std::string::npos) << e.what();
  }
}

TEST(Mobius, AlignsMarkersAndKeepsTheDisk) {
  const Complex p = std::polar(1.0, 0.3), q = std::polar(1.0, 2.0), r = std::polar(1.0, 4.0);
  const Mobius m = Mobius::alignMarkers(p, q, r);
  EXPECT_LT(std::abs(m(p) - 1.0), 1e-12);
  EXPECT_LT(std::abs(m(q) - Complex(0, 1)), 1e-12);
  EXPECT_LT(std::abs(m(r) + 1.0), 1e-12);
  for (double t = 0; t < 6.28; t += 0.1) EXPECT_NEAR(std::abs(m(std::polar(1.0, t))), 1.0, 1e-12);
  EXPECT_LT(std::abs(m(0.2 * p + 0.1 * q)), 1.0);
  EXPECT_LT(std::abs((m.inverse() * m)(Complex(0.3, -0.2)) - Complex(0.3, -0.2)), 1e-12);
  EXPECT_THROW(Mobius::alignMarkers(p, r, q), Error);  // clockwise
}

}  // namespace

// Distances along edges of a unit square grid (each square split by a diagonal) to its boundary:
// straight to the nearest side, min(i, j, n - i, n - j) steps (a diagonal, sqrt 2, only moves
// one step closer to at most two sides at once, never to the nearest one faster).
TEST(DiskMap, DistanceToBoundaryOnASquareGridAndAPrebuiltTriangulation) {
  const int n = 8;
  std::vector<Vec3d> points;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) points.push_back({double(i), double(j), 0.0});
  std::vector<std::array<int, 3>> triangles;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      triangles.push_back({a, b, d});
      triangles.push_back({a, d, c});
    }
  const IntrinsicTriangulation tri = buildTriangulation(static_cast<int>(points.size()), triangles);
  const std::vector<double> distance = distanceToBoundary(tri, embeddedEdgeLengths(tri, points));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      EXPECT_EQ(distance[j * (n + 1) + i], std::min({i, j, n - i, n - j})) << i << "," << j;

  // The prebuilt triangulation gives the same map bit for bit; one of another mesh is refused.
  const DiskMap own = computeDiskMap(points, triangles);
  const DiskMap prebuilt = computeDiskMap(points, triangles, tri);
  ASSERT_EQ(own.uv.size(), prebuilt.uv.size());
  for (std::size_t v = 0; v < own.uv.size(); ++v) ASSERT_EQ(own.uv[v], prebuilt.uv[v]);
  const std::vector<std::array<int, 3>> fewer(triangles.begin(), triangles.end() - 2);
  const IntrinsicTriangulation other = buildTriangulation(static_cast<int>(points.size()), fewer);
  EXPECT_THROW(computeDiskMap(points, triangles, other), Error);
}
