#include "confvis/backends/vulkan/byo_descriptors.hpp"

#include "confvis/backends/vulkan/warp_interface.hpp"
#include "memory.hpp"
#include "vk_check.hpp"

namespace confvis::vulkan {

VkDescriptorPool makeDescriptorPool(VkDevice device, std::span<const VkDescriptorPoolSize> sizes,
                                    std::uint32_t maxSets) {
  VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  info.maxSets = maxSets;
  info.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
  info.pPoolSizes = sizes.data();
  VkDescriptorPool pool = VK_NULL_HANDLE;
  check(vkCreateDescriptorPool(device, &info, nullptr, &pool), "vkCreateDescriptorPool");
  return pool;
}

std::vector<VkDescriptorSet> allocateDescriptorSets(VkDevice device, VkDescriptorPool pool,
                                                    std::span<const VkDescriptorSetLayout> layouts) {
  std::vector<VkDescriptorSet> sets(layouts.size(), VK_NULL_HANDLE);
  if (layouts.empty()) return sets;
  VkDescriptorSetAllocateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  info.descriptorPool = pool;
  info.descriptorSetCount = static_cast<std::uint32_t>(layouts.size());
  info.pSetLayouts = layouts.data();
  check(vkAllocateDescriptorSets(device, &info, sets.data()), "vkAllocateDescriptorSets");
  return sets;
}

VkDescriptorSetLayout makeDescriptorSetLayout(
    VkDevice device, std::span<const VkDescriptorSetLayoutBinding> bindings) {
  VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  info.bindingCount = static_cast<std::uint32_t>(bindings.size());
  info.pBindings = bindings.data();
  VkDescriptorSetLayout layout = VK_NULL_HANDLE;
  check(vkCreateDescriptorSetLayout(device, &info, nullptr, &layout),
        "vkCreateDescriptorSetLayout");
  return layout;
}

VkDescriptorSetLayout makeWarpSetLayout(VkDevice device, VkShaderStageFlags warpStages) {
  // The ray map: warp.geom and the tessellation evaluation (confvis_warp_tese.glsl) read it.
  const auto bindings = warpSetLayoutBindings(
      warpStages, VK_SHADER_STAGE_GEOMETRY_BIT |
                      (warpStages & VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT));
  return makeDescriptorSetLayout(device, bindings);
}

void writeWarpSet(VkDevice device, VkDescriptorSet set, const UploadedRetargetMap& map) {
  writeImageDescriptor(device, set, kWarpBinding, map.sampler(), map.geomView());
  writeImageDescriptor(device, set, kCoverageBinding, map.sampler(), map.rayView());
}

}  // namespace confvis::vulkan
