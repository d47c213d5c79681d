#pragma once
// A Scene on the device: one interleaved vertex buffer and one index buffer for all meshes (also
// read as storage buffers by the conformal pre-pass), base-colour textures as float images, one
// descriptor set per texture (plus a white one). The vertex buffer holds more than the scene's
// vertices: conformal draws split triangles at their edges' midpoints and along the source's cut
// (classify_bent_triangles.comp, split_triangles_at_cut.comp), and drawing those pieces from the
// same buffer by index, with fixed-function vertex fetch and the vertex cache, costs a fraction
// of a vertex shader that assembles them (lavapipe: ~0.015 s a 20k-triangle frame under a baked
// map).
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "confvis/engine/scene.hpp"
#include "context.hpp"
#include "memory.hpp"
#include "pipelines.hpp"

namespace confvis::vulkan {

class GpuScene {
 public:
  // Validates the scene (Error(InvalidInput) naming the culprit) and uploads it.
  GpuScene(VulkanContext& context, const Pipelines& pipelines, const Scene& scene);

  struct Draw;
  // Geometry alone, without textures (the bring-your-own pre-pass step, byo_prepass.cpp): the
  // draws' materials stay VK_NULL_HANDLE. `name` names the geometry in errors.
  GpuScene(VulkanContext& context, std::vector<Vertex> vertices,
           const std::vector<std::uint32_t>& indices, std::vector<Draw> draws,
           const std::string& name);

  struct Draw {
    std::uint32_t firstIndex = 0, indexCount = 0;
    std::int32_t vertexOffset = 0;
    glm::vec4 baseColorFactor{1.0f};
    VkDescriptorSet material = VK_NULL_HANDLE;  // base-colour texture (white when none)
    bool hasNormals = false;
  };
  const std::vector<Draw>& draws() const { return draws_; }
  VkBuffer vertexBuffer() const { return vertices_.get(); }
  VkBuffer indexBuffer() const { return indices_.get(); }
  // The distinct edges (uvec2 of vertex indices) and each triangle's edges, laid out like the
  // indices (mesh_edges.hpp); texel buffers for the conformal pre-pass.
  VkBuffer edgeBuffer() const { return edges_.get(); }
  VkBuffer triangleEdgeBuffer() const { return triangleEdges_.get(); }
  std::size_t edgeCount() const { return edgeCount_; }
  const Bounds& bounds() const { return bounds_; }
  std::size_t triangleCount() const { return triangleCount_; }
  std::size_t vertexCount() const { return vertexCount_; }
  // The vertex buffer's layout: the scene's vertices; from midpointBase() on, edge e's midpoint
  // at midpointBase() + e (position, normal and uv averaged; the pre-pass measures its warp);
  // from cutVertexBase() on, cutVertexCapacity() slots the pre-pass fills with points on the
  // source's cut. The bases are multiples of 16, so that per-vertex arrays of vec4 split at them
  // satisfy every device's storage-buffer offset alignment (at most 256 bytes).
  std::uint32_t midpointBase() const { return midpointBase_; }
  std::uint32_t cutVertexBase() const { return cutVertexBase_; }
  std::uint32_t cutVertexCapacity() const { return cutVertexCapacity_; }
  std::size_t extendedVertexCount() const {
    return std::size_t{cutVertexBase_} + cutVertexCapacity_;
  }
  // Distinct for every GpuScene ever built, so that derived buffers know when to rebuild.
  std::uint64_t id() const { return id_; }

 private:
  // Everything but the textures: edges, midpoints, cut slots, the buffers (both constructors).
  void uploadGeometry(VulkanContext& context, std::vector<Vertex> vertices,
                      const std::vector<std::uint32_t>& indices);
  // Appends the edge midpoints and the cut-vertex slots to `vertices` (the layout above).
  void appendConformalVertices(std::vector<Vertex>& vertices, const std::vector<glm::uvec2>& edges);

  std::vector<Draw> draws_;
  Buffer vertices_, indices_, edges_, triangleEdges_;
  std::vector<Image> textures_;  // textures_.back() is the white 1x1 texture
  UniqueSampler sampler_;
  UniqueDescriptorPool pool_;
  Bounds bounds_;
  std::size_t triangleCount_ = 0;
  std::size_t vertexCount_ = 0;
  std::size_t edgeCount_ = 0;
  std::uint32_t midpointBase_ = 0, cutVertexBase_ = 0, cutVertexCapacity_ = 0;
  std::uint64_t id_ = 0;
};

}  // namespace confvis::vulkan
