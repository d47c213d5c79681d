// The repairs behind computeRealMeshDiskMap, on closed-form configurations: a folded fan is
// untangled by moving its centre into the kernel of its ring, a fold with only boundary corners
// is refused, and a flat face (a T-junction) is moved off its long edge to the side its
// neighbours face.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "confvis/conformal/distortion.hpp"
#include "confvis/conformal/real_mesh_map.hpp"

using namespace confvis::conformal;

namespace {

// A hexagonal fan: centre 0, ring 1..6 counter-clockwise in the plane z = 0.
TriMesh hexagonFan(std::vector<std::complex<double>>& uv) {
  TriMesh mesh;
  mesh.add_vertex(Vec3(0, 0, 0));
  uv = {0};
  for (int i = 0; i < 6; ++i) {
    const double t = i * std::numbers::pi / 3;
    mesh.add_vertex(Vec3(std::cos(t), std::sin(t), 0));
    uv.push_back(std::polar(1.0, t));
  }
  for (int i = 0; i < 6; ++i)
    mesh.add_face(TriMesh::VertexHandle(0), TriMesh::VertexHandle(1 + i),
                  TriMesh::VertexHandle(1 + (i + 1) % 6));
  return mesh;
}

TEST(RealMeshMap, AFoldedFanIsUntangledIntoItsKernel) {
  std::vector<std::complex<double>> uv;
  const TriMesh mesh = hexagonFan(uv);
  EXPECT_TRUE(foldedTriangles(mesh, uv).empty());
  // The centre pushed just past the ring edge between vertices 1 and 2: face (0, 1, 2) folds.
  const std::complex<double> edgeMid = 0.5 * (uv[1] + uv[2]);
  uv[0] = edgeMid * 1.01;
  ASSERT_EQ(foldedTriangles(mesh, uv), std::vector<int>{0});
  double shift = 0;
  EXPECT_EQ(untangleFolds(mesh, uv, shift), 1);
  EXPECT_TRUE(foldedTriangles(mesh, uv).empty());
  // Back inside the hexagon, near where it was: the move is about the 1 % overshoot.
  EXPECT_LT(std::abs(uv[0]), std::abs(edgeMid));
  EXPECT_LT(std::abs(uv[0] - edgeMid * 1.01), 0.02);
  EXPECT_GT(shift, 0);
  EXPECT_LT(shift, 0.05);
}

TEST(RealMeshMap, AFoldWithOnlyBoundaryCornersIsNotUntangled) {
  TriMesh mesh;
  for (const auto& p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}) mesh.add_vertex(p);
  mesh.add_face(TriMesh::VertexHandle(0), TriMesh::VertexHandle(1), TriMesh::VertexHandle(2));
  std::vector<std::complex<double>> uv = {0, {0, 1}, 1};  // clockwise
  double shift = 0;
  EXPECT_EQ(untangleFolds(mesh, uv, shift), -1);
}

TEST(RealMeshMap, AFlatFaceIsMovedOffItsLongEdgeTowardsItsNeighboursSide) {
  // Square (0,0)-(2,0)-(2,2)-(0,2) split at the midpoint m = (1,0,0) of its bottom edge, which
  // a flat face (a, b, m) closes against the triangle (b, a, d) below: a T-junction.
  TriMesh mesh;
  const Vec3 a(0, 0, 0), b(2, 0, 0), c(2, 2, 0), e(0, 2, 0), m(1, 0, 0), d(1, -1, 0);
  for (const auto& p : {a, b, c, e, m, d}) mesh.add_vertex(p);
  auto face = [&](int i, int j, int k) {
    ASSERT_TRUE(mesh.add_face(TriMesh::VertexHandle(i), TriMesh::VertexHandle(j),
                              TriMesh::VertexHandle(k)).is_valid());
  };
  face(0, 4, 3);  // a m e
  face(4, 1, 2);  // m b c
  face(4, 2, 3);  // m c e
  face(1, 4, 0);  // the flat face b m a: a-m-b on a line
  face(1, 0, 5);  // b a d
  TriMesh moved = mesh;
  EXPECT_EQ(mollifyDegenerateFaces(moved), 1);
  const Vec3 shifted = moved.point(TriMesh::VertexHandle(4));
  // Up (+z crossed with the long edge a→b), by 1e-4 / (1/|am| + 1/|mb|).
  EXPECT_NEAR(shifted[1], 0.5e-4, 1e-12) << "m left of a→b, as the face (b, m, a) needs";
  EXPECT_DOUBLE_EQ(shifted[0], 1);
  EXPECT_DOUBLE_EQ(shifted[2], 0);
  const Vec3 n = moved.calc_face_normal(TriMesh::FaceHandle(3));
  EXPECT_GT(n[2], 0.99) << "the flat face now faces the way its neighbours do";
  // A face with slack is left alone.
  TriMesh again = moved;
  EXPECT_EQ(mollifyDegenerateFaces(again), 0);
  // In the input the flat face has no orientation: a counter-clockwise image of it is not
  // counted as flipped, a clockwise one is.
  std::vector<std::complex<double>> uv;
  for (const auto& p : {a, b, c, e, m, d}) uv.emplace_back(p[0], p[1]);
  uv[4] += std::complex<double>(0, 1e-3);
  DistortionStats stats = measureDistortion(mesh, uv);
  EXPECT_EQ(stats.flippedFaces, 0);
  EXPECT_EQ(stats.degenerateFaces, 1);
  uv[4] -= std::complex<double>(0, 2e-3);
  stats = measureDistortion(mesh, uv);
  EXPECT_EQ(stats.flippedFaces, 1);
  EXPECT_EQ(stats.degenerateFaces, 0);
}

}  // namespace
