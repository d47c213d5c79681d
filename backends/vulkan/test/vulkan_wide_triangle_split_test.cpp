// The split of wide triangles before the warp (wide_triangle_split.hpp): pieces no wider than
// the bound seen from the centre, no cracks (every inner edge shared by two pieces in opposite
// directions, so no T-junction), the same surface, orientation and attributes.
#include <gtest/gtest.h>

#include <map>

#include "../src/wide_triangle_split.hpp"
#include "vulkan_test_scenes.hpp"

namespace confvis::vulkan {
namespace {

double angleDegrees(glm::dvec3 a, glm::dvec3 b) {
  return glm::degrees(std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)));
}

Scene nearQuadAndSmallTriangle() {
  Scene scene;
  scene.meshes.push_back(test::quad("near quad", {0.0f, 0.0f, -0.5f}, {10.0f, 0.0f, 0.0f},
                                    {0.0f, 10.0f, 0.0f}, -1, 40.0f));
  scene.meshes.push_back(test::quad("far quad", {0.0f, 0.0f, -50.0f}, {1.0f, 0.0f, 0.0f},
                                    {0.0f, 1.0f, 0.0f}, -1));
  return scene;
}

double area(const Mesh& mesh) {
  double total = 0.0;
  for (const glm::uvec3& t : mesh.triangles)
    total += 0.5 * glm::length(glm::cross(glm::dvec3(mesh.positions[t.y] - mesh.positions[t.x]),
                                          glm::dvec3(mesh.positions[t.z] - mesh.positions[t.x])));
  return total;
}

TEST(WideTriangleSplit, SplitsOnlyWideTrianglesIntoNarrowConformingPieces) {
  const Scene scene = nearQuadAndSmallTriangle();
  const glm::dvec3 centre(0.0);
  const double bound = 8.0;
  EXPECT_TRUE(hasWideTriangles(scene, centre, bound));
  const WideTriangleSplit split = splitWideTriangles(scene, centre, bound);
  EXPECT_EQ(split.trianglesSplit, 2u);  // the near quad's two; the far quad spans 2.3 degrees
  EXPECT_FALSE(hasWideTriangles(split.scene, centre, bound));
  EXPECT_EQ(split.scene.meshes[1].triangles, scene.meshes[1].triangles);

  const Mesh& pieces = split.scene.meshes[0];
  EXPECT_GT(pieces.triangles.size(), 100u);
  EXPECT_NEAR(area(pieces), area(scene.meshes[0]), 1e-3 * area(scene.meshes[0]));
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directedEdges;
  for (const glm::uvec3& t : pieces.triangles) {
    const glm::dvec3 a(pieces.positions[t.x]), b(pieces.positions[t.y]), c(pieces.positions[t.z]);
    EXPECT_GT(glm::cross(b - a, c - a).z, 0.0);  // facing +z as the quad does
    for (auto [i, j] : {std::pair{t.x, t.y}, {t.y, t.z}, {t.z, t.x}}) {
      EXPECT_LE(angleDegrees(glm::dvec3(pieces.positions[i]) - centre,
                             glm::dvec3(pieces.positions[j]) - centre), bound + 1e-6);
      ++directedEdges[{i, j}];
    }
  }
  // Inner edges appear once each way; an edge without its reverse lies on the quad's border.
  for (const auto& [edge, count] : directedEdges) {
    EXPECT_EQ(count, 1);
    if (!directedEdges.count({edge.second, edge.first})) {
      const glm::vec3 a = pieces.positions[edge.first], b = pieces.positions[edge.second];
      const bool onBorder = (std::abs(std::abs(a.x) - 10.0f) < 1e-4f && a.x == b.x) ||
                            (std::abs(std::abs(a.y) - 10.0f) < 1e-4f && a.y == b.y);
      EXPECT_TRUE(onBorder) << a.x << "," << a.y << " -> " << b.x << "," << b.y;
    }
  }
  // uv is affine on the quad (test::quad: u = 2 (x + 10), v = 2 (10 - y)), normals kept.
  for (std::size_t v = 0; v < pieces.positions.size(); ++v) {
    EXPECT_NEAR(pieces.uvs[v].x, 2.0f * (pieces.positions[v].x + 10.0f), 1e-3f);
    EXPECT_NEAR(pieces.uvs[v].y, 2.0f * (10.0f - pieces.positions[v].y), 1e-3f);
    EXPECT_EQ(pieces.normals[v], glm::vec3(0.0f, 0.0f, 1.0f));
  }
}

TEST(WideTriangleSplit, NarrowScenesAndCornersAtTheCentreAreLeftAlone) {
  const Scene scene = nearQuadAndSmallTriangle();
  EXPECT_FALSE(hasWideTriangles(scene, glm::dvec3(0.0, 0.0, 1000.0), 8.0));
  Scene fan;
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, -1}, {-1, 0, -1}};
  mesh.triangles = {{0, 1, 2}};
  fan.meshes.push_back(mesh);
  // Seen from its own corner the triangle spans 90 degrees between the other two corners.
  EXPECT_TRUE(hasWideTriangles(fan, glm::dvec3(0.0), 30.0));
  const WideTriangleSplit split = splitWideTriangles(fan, glm::dvec3(0.0), 30.0);
  EXPECT_EQ(split.scene.meshes[0].triangles.size(), 3u);  // the far edge cut in three
  EXPECT_FALSE(hasWideTriangles(split.scene, glm::dvec3(0.0), 30.0 + 1e-4));  // float positions
}

}  // namespace
}  // namespace confvis::vulkan
