#include "confvis/conformal/intrinsic_triangulation.hpp"

#include <gtest/gtest.h>

#include "confvis/base/error.hpp"
#include "confvis/conformal/mesh_generators.hpp"

using namespace confvis;
using namespace confvis::conformal;

namespace {
void expectSame(const IntrinsicTriangulation& a, const IntrinsicTriangulation& b) {
  EXPECT_EQ(a.vertexCount, b.vertexCount);
  EXPECT_EQ(a.faceVertices, b.faceVertices);
  EXPECT_EQ(a.faceEdges, b.faceEdges);
  EXPECT_EQ(a.edgeVertices, b.edgeVertices);
  EXPECT_EQ(a.edgeFaces, b.edgeFaces);
  EXPECT_EQ(a.vertexOnBoundary, b.vertexOnBoundary);
}
}  // namespace

// The disk map derives its annulus from the whole triangulation; the flow's result depends on
// the edge numbering, so it must be exactly the one buildTriangulation gives when skipping.
TEST(IntrinsicTriangulation, WithoutFaceNumbersAsBuildingWithoutIt) {
  const TriMesh mesh = makeLopsidedDisk(9, 0.2, 3);
  const auto triangles = meshTriangles(mesh);
  const int n = static_cast<int>(mesh.n_vertices());
  const IntrinsicTriangulation whole = buildTriangulation(n, triangles);
  int boundaryFace = -1;
  for (int f = 0; f < whole.faceCount() && boundaryFace < 0; ++f)
    for (int e : whole.faceEdges[f])
      if (whole.edgeOnBoundary(e)) boundaryFace = f;
  ASSERT_GE(boundaryFace, 0);
  // Face 0 and an interior face in the middle: the removed face is the first to reach some of
  // its edges in the one and not in the other, so both renumbering cases occur.
  for (int face : {0, whole.faceCount() / 2, boundaryFace, whole.faceCount() - 1}) {
    SCOPED_TRACE(face);
    expectSame(withoutFace(whole, face), buildTriangulation(n, triangles, face));
  }
  EXPECT_THROW(withoutFace(whole, whole.faceCount()), Error);
}
