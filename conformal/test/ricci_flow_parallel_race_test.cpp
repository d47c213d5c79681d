// The Ricci flow's parallel loops (metric evaluation, Newton assembly: ricci_flow_parallel.hpp)
// split only meshes of two grains (2 x 20 000 edges or faces) or more, so the flow tests' small
// meshes never start a thread. This disk is large enough that every loop splits on a machine of
// two or more cores, and runs in ThreadSanitizer's suite (tools/sanitizers/tsan.sh).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <thread>

#include "confvis/conformal/intrinsic_triangulation.hpp"
#include "confvis/conformal/mesh_generators.hpp"
#include "confvis/conformal/ricci_flow.hpp"

using namespace confvis;
using namespace confvis::conformal;

TEST(RicciFlowParallelRace, DiskOfManyGrainsFlattensWithRoundBoundaryOnEveryCore) {
  if (std::thread::hardware_concurrency() < 2) GTEST_SKIP() << "one core: the loops never split";
  TriMesh mesh = makeRoundDisk(145, 0.1, 3);  // 2 x 145² = 42 050 faces, ~63 000 edges
  auto tri = buildTriangulation(mesh);
  ASSERT_GE(tri.faceCount(), 40000);
  auto metric = initialMetric(tri, embeddedEdgeLengths(tri, mesh), Scheme::Yamabe,
                              Geometry::Euclidean);
  int boundary = 0;
  for (char b : tri.vertexOnBoundary) boundary += b;
  std::vector<double> target(tri.vertexCount, 0.0);
  for (int v = 0; v < tri.vertexCount; ++v)
    if (tri.vertexOnBoundary[v]) target[v] = 2 * std::numbers::pi / boundary;
  const RicciFlowReport report = runRicciFlow(tri, metric, target);
  const std::vector<double> K = vertexCurvature(tri, metric);
  double maxError = 0;
  for (int v = 0; v < tri.vertexCount; ++v) maxError = std::max(maxError, std::abs(K[v] - target[v]));
  EXPECT_LE(maxError, 1e-9);
  EXPECT_LT(report.iterations, 30);
}
