#include "flat_wall_cull.hpp"

#include <array>

#include <stdint.h>  // the generated SPIR-V headers use ::uint32_t

#include "confvis/backends/vulkan/byo_descriptors.hpp"
#include "gpu_scene.hpp"
#include "vk_check.hpp"

#include "confvis_spirv/cull_flat_per_wall_comp.h"

namespace confvis::vulkan {
namespace {

// Push constant block `Cull` of cull_flat_per_wall.comp.
struct CullConstants {
  std::uint32_t triangles, firstIndex;
  std::int32_t vertexOffset;
  std::uint32_t mesh, meshes, walls, eyes, wallStride, broken;
};
constexpr std::uint32_t kCullGroup = 64;  // its local size

}  // namespace

FlatWallCull::FlatWallCull(VulkanContext& context, const Pipelines& pipelines)
    : context_(context) {
  const VkDevice device = context.device();
  setLayout_ = computeBuffersSetLayout(device, 4);
  layout_ = pipelineLayout(device, {pipelines.frameSetLayout(), setLayout_.get()},
                           {VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(CullConstants)});
  pipeline_ = computePipeline(device, layout_.get(),
                              shaderModule(device, kSpirv_cull_flat_per_wall_comp));
  const std::array<VkDescriptorPoolSize, 1> sizes = {{{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 4}}};
  pool_ = UniqueDescriptorPool(device, makeDescriptorPool(device, sizes, 1));
  const std::array<VkDescriptorSetLayout, 1> layouts = {setLayout_.get()};
  set_ = allocateDescriptorSets(device, pool_.get(), layouts)[0];
}

VkDeviceSize FlatWallCull::commandOffset(std::uint32_t wall, std::size_t draw) const {
  return (wall * meshes_ + draw) * sizeof(VkDrawIndexedIndirectCommand);
}

std::uint64_t FlatWallCull::wallTriangles(std::uint32_t wall) const {
  const auto* commands = static_cast<const VkDrawIndexedIndirectCommand*>(commands_.mapped());
  std::uint64_t triangles = 0;
  for (std::size_t d = 0; d < meshes_; ++d) triangles += commands[wall * meshes_ + d].indexCount / 3;
  return triangles;
}

void FlatWallCull::record(VkCommandBuffer cmd, const GpuScene& scene, VkDescriptorSet frameSet,
                          VkBuffer flatIndices, VkBuffer warped, std::uint32_t walls,
                          std::uint32_t eyes, bool wrongFrustaForTests) {
  const VkDevice device = context_.device();
  const std::size_t meshes = scene.draws().size();
  const std::uint64_t stride = scene.triangleCount() * 3;
  const VkDeviceSize indexBytes = std::max<VkDeviceSize>(walls * stride, 1) * sizeof(std::uint32_t);
  if (indices_.size() < indexBytes) {
    indices_ = Buffer(context_, indexBytes,
                      VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false);
    writeBufferDescriptor(device, set_, 2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, indices_.get());
  }
  const VkDeviceSize commandBytes =
      std::max<VkDeviceSize>(walls * meshes, 1) * sizeof(VkDrawIndexedIndirectCommand);
  if (commands_.size() < commandBytes) {
    // Shared: reset from the host before every frame (the previous frame's draws have completed).
    commands_ = Buffer(context_, commandBytes,
                       VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                       BufferMemory::Shared);
    writeBufferDescriptor(device, set_, 3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, commands_.get());
  }
  // Always where they changed: a new buffer may reuse a freed one's handle.
  if (boundFlat_ != flatIndices || boundWarped_ != warped) {
    writeBufferDescriptor(device, set_, 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, flatIndices);
    writeBufferDescriptor(device, set_, 1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, warped);
    boundFlat_ = flatIndices;
    boundWarped_ = warped;
  }
  walls_ = walls;
  meshes_ = meshes;
  auto* commands = static_cast<VkDrawIndexedIndirectCommand*>(commands_.mapped());
  for (std::uint32_t w = 0; w < walls; ++w)
    for (std::size_t d = 0; d < meshes; ++d) {
      const GpuScene::Draw& draw = scene.draws()[d];
      commands[w * meshes + d] = {0, 1, static_cast<std::uint32_t>(w * stride + draw.firstIndex),
                                  draw.vertexOffset, 0};
    }

  // The pre-pass's flat list and warps (this submission's or an earlier one's), and the previous
  // frame's draws of the lists this one overwrites.
  VkMemoryBarrier ready{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  ready.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  ready.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
  vkCmdPipelineBarrier(cmd,
                       VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT |
                           VK_PIPELINE_STAGE_VERTEX_INPUT_BIT,
                       VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &ready, 0, nullptr, 0, nullptr);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_.get());
  const std::array<VkDescriptorSet, 2> sets = {frameSet, set_};
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_.get(), 0, 2, sets.data(),
                          0, nullptr);
  for (std::size_t d = 0; d < meshes; ++d) {
    const GpuScene::Draw& draw = scene.draws()[d];
    const CullConstants push{draw.indexCount / 3, draw.firstIndex, draw.vertexOffset,
                             static_cast<std::uint32_t>(d), static_cast<std::uint32_t>(meshes),
                             walls, eyes, static_cast<std::uint32_t>(stride),
                             wrongFrustaForTests ? 1u : 0u};
    if (push.triangles == 0) continue;
    vkCmdPushConstants(cmd, layout_.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
    vkCmdDispatch(cmd, (push.triangles + kCullGroup - 1) / kCullGroup, 1, 1);
  }
  VkMemoryBarrier toDraws{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  toDraws.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  toDraws.dstAccessMask = VK_ACCESS_INDEX_READ_BIT | VK_ACCESS_INDIRECT_COMMAND_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                       VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_VERTEX_INPUT_BIT, 0,
                       1, &toDraws, 0, nullptr, 0, nullptr);
}

}  // namespace confvis::vulkan
