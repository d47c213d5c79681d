#include "confvis/conformal/mesh.hpp"

#include <gtest/gtest.h>

#include "confvis/base/error.hpp"

using namespace confvis;
using namespace confvis::conformal;

namespace {
TriMesh square(bool withHole) {
  // 4x4 grid of vertices; optionally drop the middle quad's two faces to make an annulus.
  TriMesh m;
  std::vector<TriMesh::VertexHandle> v;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) v.push_back(m.add_vertex(Vec3(i, j, 0)));
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      if (withHole && i == 1 && j == 1) continue;
      auto a = v[j * 4 + i], b = v[j * 4 + i + 1], c = v[(j + 1) * 4 + i + 1],
           d = v[(j + 1) * 4 + i];
      m.add_face(a, b, c);
      m.add_face(a, c, d);
    }
  return m;
}
}  // namespace

TEST(MeshTopology, GridIsADisk) {
  const auto t = analyzeTopology(square(false));
  EXPECT_EQ(t.eulerCharacteristic, 1);
  EXPECT_EQ(t.boundaryLoops, 1);
  EXPECT_TRUE(t.isDisk());
}

TEST(MeshTopology, AnnulusIsRejectedWithItsNumbers) {
  const TriMesh m = square(true);
  const auto t = analyzeTopology(m);
  EXPECT_EQ(t.eulerCharacteristic, 0);
  EXPECT_EQ(t.boundaryLoops, 2);
  try {
    requireDisk(m, "test mesh");
    FAIL();
  } catch (const Error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("Euler characteristic 0"), std::string::npos) << msg;
    EXPECT_NE(msg.find("2 boundary loops"), std::string::npos) << msg;
  }
}

TEST(MeshIo, MissingFileIsNamed) {
  EXPECT_THROW(readMesh("/no/such/mesh.obj"), Error);
}
