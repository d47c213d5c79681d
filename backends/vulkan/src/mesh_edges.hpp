#pragma once
// The distinct edges of a scene's triangles, so that the conformal pre-pass warps each edge's
// midpoint and picks its tessellation level once per edge (classify_edges.comp) instead of once
// per triangle that has it, and the two triangles sharing an edge read the very same result.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace confvis::vulkan {

struct MeshEdges {
  std::vector<glm::uvec2> edges;            // vertex indices, smaller first
  std::vector<std::uint32_t> triangleEdges;  // 3 per triangle: edge k is opposite corner k
};

// One mesh's part of the index buffer; its indices count from vertexOffset.
struct IndexRange {
  std::uint32_t firstIndex, indexCount;
  std::int32_t vertexOffset;
};
// Edges keyed by vertex index (plus offset): triangles that share positions but not vertices
// (texture seams) get an edge each, computed alike. triangleEdges is laid out like `indices`.
MeshEdges buildMeshEdges(const std::vector<std::uint32_t>& indices,
                         const std::vector<IndexRange>& ranges);

}  // namespace confvis::vulkan
