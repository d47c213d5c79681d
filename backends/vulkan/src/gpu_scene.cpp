#include "gpu_scene.hpp"

#include <algorithm>
#include <atomic>
#include <limits>
#include <string>

#include "confvis/backends/vulkan/byo_descriptors.hpp"
#include "confvis/base/error.hpp"
#include "mesh_edges.hpp"
#include "vk_check.hpp"

namespace confvis::vulkan {
namespace {

Image uploadTexture(VulkanContext& context, const Texture& texture) {
  ImageSpec spec;
  spec.width = static_cast<std::uint32_t>(texture.width);
  spec.height = static_cast<std::uint32_t>(texture.height);
  spec.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  Image image(context, spec);
  uploadFloatImage(context, image, texture.rgba.data());
  return image;
}

// Bilinear with repeat wrap and texel centres at (i + 0.5) / size: Texture::sample's filtering.
UniqueSampler textureSampler(VkDevice device) {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = VK_FILTER_LINEAR;
  info.minFilter = VK_FILTER_LINEAR;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  info.addressModeV = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  info.addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT;
  VkSampler sampler = VK_NULL_HANDLE;
  check(vkCreateSampler(device, &info, nullptr, &sampler), "vkCreateSampler");
  return UniqueSampler(device, sampler);
}

}  // namespace

GpuScene::GpuScene(VulkanContext& context, const Pipelines& pipelines, const Scene& scene) {
  validateScene(scene);
  const VkDevice device = context.device();
  if (scene.vertexCount() > std::numeric_limits<std::int32_t>::max() ||
      scene.triangleCount() * 3 > std::numeric_limits<std::uint32_t>::max())
    throw Error(ErrorCode::InvalidInput,
                "scene '" + scene.name + "' is too large for 32-bit vertex indices");

  // Textures: the scene's, then white for untextured materials and meshes without uvs.
  for (const Texture& texture : scene.textures) textures_.push_back(uploadTexture(context, texture));
  Texture white;
  white.width = white.height = 1;
  white.rgba = {1.0f, 1.0f, 1.0f, 1.0f};
  textures_.push_back(uploadTexture(context, white));
  sampler_ = textureSampler(device);

  const auto setCount = static_cast<std::uint32_t>(textures_.size());
  const VkDescriptorPoolSize poolSize{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, setCount};
  pool_ = UniqueDescriptorPool(device, makeDescriptorPool(device, {&poolSize, 1}, setCount));
  const std::vector<VkDescriptorSetLayout> layouts(setCount, pipelines.materialSetLayout());
  const std::vector<VkDescriptorSet> sets = allocateDescriptorSets(device, pool_.get(), layouts);
  for (std::uint32_t i = 0; i < setCount; ++i)
    writeImageDescriptor(device, sets[i], 0, sampler_.get(), textures_[i].view());
  const VkDescriptorSet whiteSet = sets.back();

  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;
  vertices.reserve(scene.vertexCount());
  indices.reserve(scene.triangleCount() * 3);
  for (const Mesh& mesh : scene.meshes) {
    Draw draw;
    draw.firstIndex = static_cast<std::uint32_t>(indices.size());
    draw.indexCount = static_cast<std::uint32_t>(mesh.triangles.size() * 3);
    draw.vertexOffset = static_cast<std::int32_t>(vertices.size());
    draw.hasNormals = !mesh.normals.empty();
    draw.material = whiteSet;
    if (mesh.material >= 0) {
      const Material& material = scene.materials[static_cast<std::size_t>(mesh.material)];
      draw.baseColorFactor = material.baseColorFactor;
      if (material.baseColorTexture >= 0 && !mesh.uvs.empty())
        draw.material = sets[static_cast<std::size_t>(material.baseColorTexture)];
    }
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
      vertices.push_back({mesh.positions[i], draw.hasNormals ? mesh.normals[i] : glm::vec3(0.0f),
                          mesh.uvs.empty() ? glm::vec2(0.0f) : mesh.uvs[i]});
      bounds_.extend(mesh.positions[i]);
    }
    for (const glm::uvec3& t : mesh.triangles) indices.insert(indices.end(), {t.x, t.y, t.z});
    if (draw.indexCount > 0) draws_.push_back(draw);
  }
  uploadGeometry(context, std::move(vertices), indices);
}

GpuScene::GpuScene(VulkanContext& context, std::vector<Vertex> vertices,
                   const std::vector<std::uint32_t>& indices, std::vector<Draw> draws,
                   const std::string& name)
    : draws_(std::move(draws)) {
  if (vertices.size() > std::numeric_limits<std::int32_t>::max() ||
      indices.size() > std::numeric_limits<std::uint32_t>::max())
    throw Error(ErrorCode::InvalidInput, name + " is too large for 32-bit vertex indices");
  if (indices.empty())
    throw Error(ErrorCode::InvalidInput, name + " has no triangles to draw");
  for (const Vertex& v : vertices) bounds_.extend(v.position);
  uploadGeometry(context, std::move(vertices), indices);
}

void GpuScene::uploadGeometry(VulkanContext& context, std::vector<Vertex> vertices,
                              const std::vector<std::uint32_t>& indices) {
  triangleCount_ = indices.size() / 3;
  vertexCount_ = vertices.size();
  static std::atomic<std::uint64_t> nextId{1};
  id_ = nextId++;
  std::vector<IndexRange> ranges;
  for (const Draw& draw : draws_) ranges.push_back({draw.firstIndex, draw.indexCount, draw.vertexOffset});
  const MeshEdges edges = buildMeshEdges(indices, ranges);
  edgeCount_ = edges.edges.size();
  appendConformalVertices(vertices, edges.edges);
  // The conformal pre-pass reads all four through texel views (PrepassTexels) and writes the
  // cut vertices' attributes into the vertex buffer.
  constexpr VkBufferUsageFlags kTexels = VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;
  vertices_ = uploadBuffer(context, vertices.data(), vertices.size() * sizeof(Vertex),
                           VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                               kTexels);
  indices_ = uploadBuffer(context, indices.data(), indices.size() * sizeof(std::uint32_t),
                          VK_BUFFER_USAGE_INDEX_BUFFER_BIT | kTexels);
  edges_ = uploadBuffer(context, edges.edges.data(), edges.edges.size() * sizeof(glm::uvec2),
                        kTexels);
  triangleEdges_ = uploadBuffer(context, edges.triangleEdges.data(),
                                edges.triangleEdges.size() * sizeof(std::uint32_t), kTexels);
}

void GpuScene::appendConformalVertices(std::vector<Vertex>& vertices,
                                       const std::vector<glm::uvec2>& edges) {
  const auto roundUp = [](std::size_t n) { return (n + 15) / 16 * 16; };
  // Four a triangle split along the cut (split_triangles_at_cut.comp), for at most 16384 such
  // triangles; those beyond fall back to the geometry shader's drop.
  const std::size_t cutCapacity = 4 * std::clamp<std::size_t>(triangleCount_, 1, 16384);
  const std::size_t midpointBase = roundUp(vertices.size());
  const std::size_t cutBase = midpointBase + roundUp(std::max<std::size_t>(edges.size(), 1));
  if (cutBase + cutCapacity > std::numeric_limits<std::int32_t>::max())
    throw Error(ErrorCode::InvalidInput, "scene is too large for 32-bit vertex indices with its "
                                         "edge midpoints (" + std::to_string(edges.size()) +
                                             " edges)");
  vertices.resize(cutBase + cutCapacity, Vertex{});
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const Vertex& a = vertices[edges[e].x];
    const Vertex& b = vertices[edges[e].y];
    vertices[midpointBase + e] = {0.5f * (a.position + b.position), 0.5f * (a.normal + b.normal),
                                  0.5f * (a.uv + b.uv)};
  }
  midpointBase_ = static_cast<std::uint32_t>(midpointBase);
  cutVertexBase_ = static_cast<std::uint32_t>(cutBase);
  cutVertexCapacity_ = static_cast<std::uint32_t>(cutCapacity);
}

}  // namespace confvis::vulkan
