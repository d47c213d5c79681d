#include "mesh_edges.hpp"

#include <unordered_map>

namespace confvis::vulkan {

MeshEdges buildMeshEdges(const std::vector<std::uint32_t>& indices,
                         const std::vector<IndexRange>& ranges) {
  MeshEdges result;
  result.triangleEdges.assign(indices.size(), 0);
  std::unordered_map<std::uint64_t, std::uint32_t> ids;
  ids.reserve(indices.size() / 2 + 16);  // a closed mesh has 1.5 edges per triangle
  for (const IndexRange& range : ranges) {
    for (std::uint32_t base = range.firstIndex; base < range.firstIndex + range.indexCount;
         base += 3) {
      std::uint32_t v[3];
      for (int k = 0; k < 3; ++k)
        v[k] = static_cast<std::uint32_t>(range.vertexOffset + std::int64_t{indices[base + k]});
      for (int k = 0; k < 3; ++k) {
        std::uint32_t a = v[(k + 1) % 3], b = v[(k + 2) % 3];
        if (b < a) std::swap(a, b);
        const std::uint64_t key = (std::uint64_t{a} << 32) | b;
        const auto [it, added] =
            ids.try_emplace(key, static_cast<std::uint32_t>(result.edges.size()));
        if (added) result.edges.push_back({a, b});
        result.triangleEdges[base + k] = it->second;
      }
    }
  }
  return result;
}

}  // namespace confvis::vulkan
