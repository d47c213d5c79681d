// Convergence of the Newton flow for every scheme on disks, closed genus-0 surfaces and a
// surface of negative Euler characteristic; clear errors for inadmissible or unreachable targets.
#include "confvis/conformal/ricci_flow.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "confvis/base/error.hpp"
#include "confvis/conformal/mesh_generators.hpp"

using namespace confvis;
using namespace confvis::conformal;

namespace {

constexpr double kPi = std::numbers::pi;

// Flat interior, boundary turning spread evenly: Σ = 2π for a disk.
std::vector<double> roundBoundaryTarget(const IntrinsicTriangulation& tri) {
  int boundary = 0;
  for (char b : tri.vertexOnBoundary) boundary += b;
  std::vector<double> target(tri.vertexCount, 0.0);
  for (int v = 0; v < tri.vertexCount; ++v)
    if (tri.vertexOnBoundary[v]) target[v] = 2 * kPi / boundary;
  return target;
}

void expectConverged(const IntrinsicTriangulation& tri, const CirclePackingMetric& metric,
                     const std::vector<double>& target, const RicciFlowReport& report) {
  const auto K = vertexCurvature(tri, metric);
  double maxError = 0;
  for (int v = 0; v < tri.vertexCount; ++v) maxError = std::max(maxError, std::abs(K[v] - target[v]));
  EXPECT_LE(maxError, 1e-10);
  EXPECT_LE(report.maxCurvatureError, 1e-10);
  EXPECT_LT(report.iterations, 30) << "Newton should converge in a handful of iterations";
}

class EveryScheme : public testing::TestWithParam<Scheme> {};

// Flips keep the triangulation (power) Delaunay; the dissertation reports they make every
// scheme robust. Mixed (neighbouring vertices of different ε) needs them even on good meshes.
RicciFlowOptions optionsFor(Scheme scheme) {
  RicciFlowOptions options;
  options.delaunayFlips = scheme == Scheme::Mixed;
  return options;
}

TEST_P(EveryScheme, EuclideanDiskFlattensWithRoundBoundary) {
  TriMesh mesh = makeRoundDisk(10, 0.1, 3);
  auto tri = buildTriangulation(mesh);
  auto metric = initialMetric(tri, embeddedEdgeLengths(tri, mesh), GetParam(), Geometry::Euclidean);
  const auto target = roundBoundaryTarget(tri);
  const auto report = runRicciFlow(tri, metric, target, optionsFor(GetParam()));
  expectConverged(tri, metric, target, report);
}

TEST_P(EveryScheme, EuclideanClosedGenusZeroReachesNonUniformCurvature) {
  TriMesh mesh = makeIcosphere(2);
  auto tri = buildTriangulation(mesh);
  auto metric = initialMetric(tri, embeddedEdgeLengths(tri, mesh), GetParam(), Geometry::Euclidean);
  // Deliberately non-round: the 12 original icosahedron vertices carry twice the others' share.
  std::vector<double> target(tri.vertexCount, 1.0);
  for (int v = 0; v < 12; ++v) target[v] = 2.0;
  double sum = 0;
  for (double t : target) sum += t;
  for (double& t : target) t *= 4 * kPi / sum;
  const auto report = runRicciFlow(tri, metric, target, optionsFor(GetParam()));
  expectConverged(tri, metric, target, report);
}

TEST_P(EveryScheme, SphericalClosedGenusZeroBecomesTheUnitSphere) {
  TriMesh mesh = makeIcosphere(2);
  // Squash the sphere into an ellipsoid so the flow has to change the metric.
  for (auto v : mesh.vertices()) mesh.point(v)[2] *= 0.6;
  auto tri = buildTriangulation(mesh);
  auto metric = initialMetric(tri, embeddedEdgeLengths(tri, mesh), GetParam(), Geometry::Spherical);
  const std::vector<double> target(tri.vertexCount, 0.0);
  const auto report = runRicciFlow(tri, metric, target);
  expectConverged(tri, metric, target, report);
  // Gauss-Bonnet: Σ K = 4π - Area, so the triangles now tile a sphere of area 4π.
  const auto lengths = metricEdgeLengths(tri, metric);
  double area = 0;
  for (int f = 0; f < tri.faceCount(); ++f) {
    std::array<double, 3> l, a;
    for (int c = 0; c < 3; ++c) l[c] = lengths[tri.faceEdges[f][c]];
    ASSERT_TRUE(cornerAngles(Geometry::Spherical, l, a));
    area += a[0] + a[1] + a[2] - kPi;
  }
  EXPECT_NEAR(area, 4 * kPi, 1e-8);
}

TEST_P(EveryScheme, HyperbolicDiskConverges) {
  TriMesh mesh = makeRoundDisk(10, 0.1, 3);
  for (auto v : mesh.vertices()) mesh.point(v) *= 0.4;
  auto tri = buildTriangulation(mesh);
  auto metric = initialMetric(tri, embeddedEdgeLengths(tri, mesh), GetParam(), Geometry::Hyperbolic);
  auto target = roundBoundaryTarget(tri);
  for (double& t : target) t *= 1.5;  // Σ K̄ = 3π > 2π: the excess π is the hyperbolic area
  const auto report = runRicciFlow(tri, metric, target);
  expectConverged(tri, metric, target, report);
}

// A surface of negative Euler characteristic (χ = -1) in hyperbolic geometry, every scheme: with
// flips all six converge in 6-7 Newton steps (without, all stall near 4e-8 on this mesh).
TEST_P(EveryScheme, HyperbolicPairOfPantsGetsGeodesicBoundaries) {
  TriMesh mesh = makeDiskWithTwoHoles(9);
  for (auto v : mesh.vertices()) mesh.point(v) *= 0.5;
  auto tri = buildTriangulation(mesh);
  ASSERT_EQ(tri.eulerCharacteristic(), -1);
  auto metric = initialMetric(tri, embeddedEdgeLengths(tri, mesh), GetParam(), Geometry::Hyperbolic);
  const std::vector<double> target(tri.vertexCount, 0.0);  // area 2π, geodesic boundaries
  RicciFlowOptions options;
  options.delaunayFlips = true;
  const auto report = runRicciFlow(tri, metric, target, options);
  expectConverged(tri, metric, target, report);
}

// The robust schemes also handle an irregular, lopsided mesh (obtuse and sliver triangles) once
// flips keep the triangulation Delaunay.
// Virtual radius joined them with initial radii of a third of the shortest incident edge (with
// radii of the mean incident length both cases stalled).
class RobustScheme : public testing::TestWithParam<Scheme> {};

TEST_P(RobustScheme, EuclideanIrregularDiskWithFlips) {
  TriMesh mesh = makeLopsidedDisk(10, 0.3, 5);
  auto tri = buildTriangulation(mesh);
  auto metric = initialMetric(tri, embeddedEdgeLengths(tri, mesh), GetParam(), Geometry::Euclidean);
  const auto target = roundBoundaryTarget(tri);
  RicciFlowOptions options;
  options.delaunayFlips = true;
  const auto report = runRicciFlow(tri, metric, target, options);
  expectConverged(tri, metric, target, report);
}

INSTANTIATE_TEST_SUITE_P(RicciFlow, RobustScheme,
                         testing::Values(Scheme::InversiveDistance, Scheme::Yamabe,
                                         Scheme::VirtualRadius),
                         [](const testing::TestParamInfo<Scheme>& param) {
                           return std::string(toString(param.param));
                         });

INSTANTIATE_TEST_SUITE_P(RicciFlow, EveryScheme, testing::ValuesIn(kAllSchemes),
                         [](const testing::TestParamInfo<Scheme>& param) {
                           return std::string(toString(param.param));
                         });

TEST(RicciFlow, GaussBonnetViolationIsRejectedBeforeFlowing) {
  TriMesh mesh = makeGridDisk(4);
  auto tri = buildTriangulation(mesh);
  auto metric = initialMetric(tri, embeddedEdgeLengths(tri, mesh), Scheme::Yamabe, Geometry::Euclidean);
  const std::vector<double> target(tri.vertexCount, 0.0);  // sums to 0, not 2π
  try {
    runRicciFlow(tri, metric, target);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Unreachable);
    EXPECT_NE(std::string(e.what()).find("Gauss-Bonnet"), std::string::npos) << e.what();
  }
  std::vector<double> hyperbolicTarget(tri.vertexCount, 0.0);  // Σ = 0 < 2π: no positive area
  auto hyperbolic = initialMetric(tri, embeddedEdgeLengths(tri, mesh), Scheme::Yamabe, Geometry::Hyperbolic);
  EXPECT_THROW(runRicciFlow(tri, hyperbolic, hyperbolicTarget), Error);
}

// The corner (1, -1) of makeGridDisk's square grid (in a single triangle), or -1.
int gridCornerIndex(const TriMesh& mesh) {
  for (auto v : mesh.vertices())
    if (mesh.point(v)[0] == 1.0 && mesh.point(v)[1] == -1.0) return v.idx();
  return -1;
}

TEST(RicciFlow, UnreachableTargetGivesAClearErrorAndNoNaN) {
  // Corner vertex (n, 0) of this grid lies in a single triangle: curvature 0 there needs a
  // straight angle, i.e. a degenerate triangle. The flow must stop with a reason, not NaN.
  TriMesh mesh = makeGridDisk(4);
  auto tri = buildTriangulation(mesh);
  const int corner = gridCornerIndex(mesh);
  ASSERT_GE(corner, 0);
  int cornerFaces = 0;
  for (const auto& f : tri.faceVertices)
    for (int v : f) cornerFaces += v == corner;
  ASSERT_EQ(cornerFaces, 1);
  auto metric = initialMetric(tri, embeddedEdgeLengths(tri, mesh), Scheme::Yamabe, Geometry::Euclidean);
  auto target = roundBoundaryTarget(tri);
  const double moved = target[corner];
  target[corner] = 0;
  for (int v = 0; v < tri.vertexCount; ++v)
    if (tri.vertexOnBoundary[v] && v != corner) target[v] += moved / 15.0;
  try {
    runRicciFlow(tri, metric, target);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Unreachable) << e.what();
  }
  for (double u : metric.u) EXPECT_TRUE(std::isfinite(u));
}

TEST(RicciFlow, DelaunayFlipsRescueAFlowThatDegeneratesWithoutThem) {
  // A badly shaped strip: long thin triangles whose flow to a round boundary needs flips.
  TriMesh mesh = makeGridDisk(12, 0.0);
  for (auto v : mesh.vertices()) {
    auto& p = mesh.point(v);
    p = Vec3(4.0 * p[0] + 0.9 * p[1] * p[1], 0.25 * p[1], 0.0);
  }
  auto tri = buildTriangulation(mesh);
  const auto lengths = embeddedEdgeLengths(tri, mesh);
  const auto target = roundBoundaryTarget(tri);
  auto metric = initialMetric(tri, lengths, Scheme::Yamabe, Geometry::Euclidean);
  RicciFlowOptions withFlips;
  withFlips.delaunayFlips = true;
  const auto report = runRicciFlow(tri, metric, target, withFlips);
  EXPECT_GT(report.flips, 0);
  EXPECT_GE(report.symbolicAnalyses, 2);  // a new pattern after flips
  expectConverged(tri, metric, target, report);
}

// A square grid whose corner vertex `corner` (in two triangles) must open to an angle sum of
// `angleSum`, the rest of the turning spread over the other boundary vertices.
struct CornerCase {
  IntrinsicTriangulation tri;
  std::vector<double> lengths, target;
};
CornerCase openCorner(double angleSum) {
  const TriMesh mesh = makeGridDisk(6, 0.1, 1);
  CornerCase c{buildTriangulation(mesh), {}, {}};
  c.lengths = embeddedEdgeLengths(c.tri, mesh);
  std::vector<int> faces(c.tri.vertexCount, 0);
  for (const auto& fv : c.tri.faceVertices)
    for (int v : fv) ++faces[v];
  int corner = -1, boundary = 0;
  for (auto v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    if (std::abs(std::abs(p[0]) - 1) < 1e-9 && std::abs(std::abs(p[1]) - 1) < 1e-9 &&
        faces[v.idx()] == 2)
      corner = v.idx();
    boundary += c.tri.vertexOnBoundary[v.idx()];
  }
  EXPECT_GE(corner, 0);
  c.target.assign(c.tri.vertexCount, 0.0);
  const double cornerCurvature = kPi - angleSum;
  for (int v = 0; v < c.tri.vertexCount; ++v)
    if (c.tri.vertexOnBoundary[v] && v != corner)
      c.target[v] = (2 * kPi - cornerCurvature) / (boundary - 1);
  c.target[corner] = cornerCurvature;
  return c;
}

TEST(RicciFlow, FlipsWhenStuckComeOnMidFlowOnlyWhenAStepCollapses) {
  RicciFlowOptions whenStuck;
  whenStuck.flipsWhenStuck = true;
  {  // The corner opens to 1.85π: without flips its two triangles degenerate.
    CornerCase c = openCorner(1.85 * kPi);
    auto plain = c.tri;
    auto metric = initialMetric(plain, c.lengths, Scheme::Yamabe, Geometry::Euclidean);
    EXPECT_THROW(runRicciFlow(plain, metric, c.target), Error);
    metric = initialMetric(c.tri, c.lengths, Scheme::Yamabe, Geometry::Euclidean);
    const auto report = runRicciFlow(c.tri, metric, c.target, whenStuck);
    EXPECT_GE(report.flipsStartedAt, 1) << "switched on mid-flow, not restarted";
    EXPECT_GT(report.flips, 0);
    expectConverged(c.tri, metric, c.target, report);
  }
  {  // 1.3π is reachable as it is: no flips.
    CornerCase c = openCorner(1.3 * kPi);
    auto metric = initialMetric(c.tri, c.lengths, Scheme::Yamabe, Geometry::Euclidean);
    const auto report = runRicciFlow(c.tri, metric, c.target, whenStuck);
    EXPECT_EQ(report.flipsStartedAt, -1);
    EXPECT_EQ(report.flips, 0);
    expectConverged(c.tri, metric, c.target, report);
  }
}

TEST(RicciFlow, FlipsWhenStuckStartAtOnceWhereAnAngleIsOutOfReach) {
  // The grid corner of UnreachableTargetGivesAClearErrorAndNoNaN: one triangle, target angle π.
  TriMesh mesh = makeGridDisk(4);
  auto tri = buildTriangulation(mesh);
  const int corner = gridCornerIndex(mesh);
  ASSERT_GE(corner, 0);
  auto target = roundBoundaryTarget(tri);
  const double moved = target[corner];
  target[corner] = 0;
  for (int v = 0; v < tri.vertexCount; ++v)
    if (tri.vertexOnBoundary[v] && v != corner) target[v] += moved / 15.0;
  auto metric = initialMetric(tri, embeddedEdgeLengths(tri, mesh), Scheme::Yamabe, Geometry::Euclidean);
  RicciFlowOptions whenStuck;
  whenStuck.flipsWhenStuck = true;
  const auto report = runRicciFlow(tri, metric, target, whenStuck);
  EXPECT_EQ(report.flipsStartedAt, 0);
  expectConverged(tri, metric, target, report);
}

TEST(RicciFlow, FrozenFactorIsReusedAndConvergenceStaysQuadratic) {
  TriMesh mesh = makeLopsidedDisk(12, 0.3, 2);
  auto tri = buildTriangulation(mesh);
  auto metric = initialMetric(tri, embeddedEdgeLengths(tri, mesh), Scheme::InversiveDistance,
                              Geometry::Euclidean);
  const auto report = runRicciFlow(tri, metric, roundBoundaryTarget(tri));
  EXPECT_EQ(report.symbolicAnalyses, 1);
  // Between factorisations the Newton systems are solved by CG preconditioned with the frozen
  // factor, so there are fewer factorisations than iterations.
  EXPECT_LT(report.factorizations, report.iterations);
  EXPECT_GT(report.cgIterations, 0);
  // Inexact Newton with forcing min(0.1, error): the error still falls quadratically at the end
  // (the last step only solves as accurately as the 1e-10 tolerance needs).
  const auto& h = report.errorHistory;
  ASSERT_GE(h.size(), 3u);
  EXPECT_LT(h.back(), 1e-10);
  for (std::size_t k = 0; k + 1 < h.size(); ++k)
    if (h[k] < 1e-3 && h[k + 1] > 1e-10) {
      EXPECT_LT(h[k + 1], 10 * h[k] * h[k]) << "step " << k;
    }
}

}  // namespace
