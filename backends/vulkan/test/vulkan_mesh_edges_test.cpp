// The distinct edges the conformal pre-pass measures once each (mesh_edges.hpp): shared edges
// are found once for both triangles, whatever their winding, and meshes with their own vertex
// offsets do not share edges by accident.
#include <gtest/gtest.h>

#include "../src/mesh_edges.hpp"

namespace confvis::vulkan {
namespace {

TEST(VulkanMeshEdges, TwoTrianglesOfAQuadShareTheirDiagonalOnly) {
  // Quad 0-1-2-3 split along 0-2; both triangles counter-clockwise.
  const std::vector<std::uint32_t> indices = {0, 1, 2, 0, 2, 3};
  const MeshEdges e = buildMeshEdges(indices, {{0, 6, 0}});
  ASSERT_EQ(e.edges.size(), 5u);
  ASSERT_EQ(e.triangleEdges.size(), 6u);
  // Edge opposite corner 1 of triangle 0 (0-2) is the edge opposite corner 2 of triangle 1.
  EXPECT_EQ(e.triangleEdges[1], e.triangleEdges[3 + 2]);
  EXPECT_EQ(e.edges[e.triangleEdges[1]], glm::uvec2(0, 2));
  // Edge opposite corner 0 of triangle 0 is 1-2, smaller index first.
  EXPECT_EQ(e.edges[e.triangleEdges[0]], glm::uvec2(1, 2));
  std::vector<std::uint32_t> ids(e.triangleEdges);
  std::sort(ids.begin(), ids.end());
  EXPECT_EQ(std::unique(ids.begin(), ids.end()) - ids.begin(), 5);
}

TEST(VulkanMeshEdges, MeshesAreKeyedByTheirOffsetVertices) {
  // The same local triangle in two meshes, the second's vertices 3 further on.
  const std::vector<std::uint32_t> indices = {0, 1, 2, 0, 1, 2};
  const MeshEdges e = buildMeshEdges(indices, {{0, 3, 0}, {3, 3, 3}});
  ASSERT_EQ(e.edges.size(), 6u);
  EXPECT_EQ(e.edges[e.triangleEdges[3]], glm::uvec2(4, 5));
}

}  // namespace
}  // namespace confvis::vulkan
