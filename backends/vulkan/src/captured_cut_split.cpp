#include "captured_cut_split.hpp"

#include <algorithm>
#include <array>
#include <cstring>

#include <stdint.h>  // the generated SPIR-V headers use ::uint32_t

#include "confvis/backends/vulkan/byo_descriptors.hpp"
#include "vk_check.hpp"

#include "confvis_spirv/find_captured_torn_pieces_comp.h"
#include "confvis_spirv/split_captured_at_cut_comp.h"

namespace confvis::vulkan {
namespace {

// Push constant block `CapturedSplit` of confvis_captured_split.glsl.
struct SplitConstants {
  std::uint32_t firstTriangle, capacity, region, snapToRim;
};
constexpr std::uint32_t kFindGroup = 64;   // find_captured_torn_pieces.comp's local size
constexpr VkDeviceSize kTornHeader = 16;   // count, then the indirect dispatch's x, y, z

}  // namespace

CapturedCutSplit::CapturedCutSplit(VulkanContext& context, const Pipelines& pipelines)
    : context_(context) {
  const VkDevice device = context.device();
  setLayout_ = computeBuffersSetLayout(device, 3);
  layout_ = pipelineLayout(
      device, {pipelines.frameSetLayout(), pipelines.warpSetLayout(), setLayout_.get()},
      {VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(SplitConstants)});
  find_ = computePipeline(device, layout_.get(),
                          shaderModule(device, kSpirv_find_captured_torn_pieces_comp));
  split_ = computePipeline(device, layout_.get(),
                           shaderModule(device, kSpirv_split_captured_at_cut_comp));
  const std::array<VkDescriptorPoolSize, 1> sizes = {{{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 3}}};
  pool_ = UniqueDescriptorPool(device, makeDescriptorPool(device, sizes, 1));
  const std::array<VkDescriptorSetLayout, 1> layouts = {setLayout_.get()};
  set_ = allocateDescriptorSets(device, pool_.get(), layouts)[0];
}

void CapturedCutSplit::bind(VkBuffer captured, std::uint64_t triangles, std::uint32_t queries) {
  const VkDevice device = context_.device();
  // Every piece takes three triangles.
  const VkDeviceSize tornBytes = kTornHeader + (triangles / 3 + 1) * sizeof(std::uint32_t);
  if (torn_.size() < tornBytes) {
    torn_ = Buffer(context_, tornBytes,
                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                       VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                   BufferMemory::Shared);
    writeBufferDescriptor(device, set_, 1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, torn_.get());
  }
  const VkDeviceSize writtenBytes = std::max<VkDeviceSize>(queries, 1) * 2 * sizeof(std::uint32_t);
  if (written_.size() < writtenBytes) {
    written_ = Buffer(context_, writtenBytes,
                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                      BufferMemory::Device);
    writeBufferDescriptor(device, set_, 2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, written_.get());
  }
  // Always: a new buffer may reuse a freed one's handle.
  writeBufferDescriptor(device, set_, 0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, captured);
}

void CapturedCutSplit::record(VkCommandBuffer cmd, VkQueryPool queries, std::uint32_t queryCount,
                              const std::vector<Region>& regions, VkDescriptorSet frameSet,
                              VkDescriptorSet warpSet, bool snapToRim) {
  const std::array<std::uint32_t, 4> header = {0, 0, 1, 1};
  vkCmdUpdateBuffer(cmd, torn_.get(), 0, sizeof(header), header.data());
  if (queryCount > 0)
    vkCmdCopyQueryPoolResults(cmd, queries, 0, queryCount, written_.get(), 0,
                              2 * sizeof(std::uint32_t), VK_QUERY_RESULT_WAIT_BIT);
  // The captured records (transform feedback) and the two transfers, to the passes.
  VkMemoryBarrier toCompute{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  toCompute.srcAccessMask =
      VK_ACCESS_TRANSFORM_FEEDBACK_WRITE_BIT_EXT | VK_ACCESS_TRANSFER_WRITE_BIT;
  toCompute.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
  vkCmdPipelineBarrier(cmd,
                       VK_PIPELINE_STAGE_TRANSFORM_FEEDBACK_BIT_EXT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &toCompute, 0, nullptr, 0,
                       nullptr);
  const std::array<VkDescriptorSet, 3> sets = {frameSet, warpSet, set_};
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_.get(), 0, 3, sets.data(),
                          0, nullptr);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, find_.get());
  for (const Region& region : regions) {
    if (region.capacity == 0) continue;
    const SplitConstants push{region.firstTriangle, region.capacity, region.query,
                              snapToRim ? 1u : 0u};
    vkCmdPushConstants(cmd, layout_.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
    vkCmdDispatch(cmd, (region.capacity + kFindGroup - 1) / kFindGroup, 1, 1);
  }
  VkMemoryBarrier listed{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  listed.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  listed.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_INDIRECT_COMMAND_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                       VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT, 0,
                       1, &listed, 0, nullptr, 0, nullptr);
  const SplitConstants push{0, 0, 0, snapToRim ? 1u : 0u};
  vkCmdPushConstants(cmd, layout_.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, split_.get());
  vkCmdDispatchIndirect(cmd, torn_.get(), sizeof(std::uint32_t));
}

std::uint32_t CapturedCutSplit::tornPieces() const {
  std::uint32_t count = 0;
  if (torn_.mapped()) std::memcpy(&count, torn_.mapped(), sizeof(count));
  return count;
}

}  // namespace confvis::vulkan
