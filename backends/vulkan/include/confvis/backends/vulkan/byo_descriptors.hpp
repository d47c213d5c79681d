#pragma once
// Descriptor pools and sets on the application's device, as the backend makes its own (frame,
// warp and pre-pass sets): a pool sized for a known set of layouts, then one set per layout.
// tools/byo_vulkan_example allocates its frame, warp and material sets with these.
// Thread-safety: free functions; a pool must not be used from two threads at once (Vulkan's
// external synchronization rule for vkAllocateDescriptorSets).
#include <cstdint>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {
namespace vulkan CONFVIS_API {

// A pool for at most `maxSets` sets holding `sizes` descriptors in all; the caller destroys it
// (vkDestroyDescriptorPool, which frees its sets). Throws Error(Internal) naming
// vkCreateDescriptorPool where the device refuses.
VkDescriptorPool makeDescriptorPool(VkDevice device, std::span<const VkDescriptorPoolSize> sizes,
                                    std::uint32_t maxSets);

// One set per entry of `layouts`, in their order, from `pool`. Throws Error(Internal) naming
// vkAllocateDescriptorSets where the pool is too small.
std::vector<VkDescriptorSet> allocateDescriptorSets(VkDevice device, VkDescriptorPool pool,
                                                    std::span<const VkDescriptorSetLayout> layouts);

}  // namespace vulkan
}  // namespace confvis
