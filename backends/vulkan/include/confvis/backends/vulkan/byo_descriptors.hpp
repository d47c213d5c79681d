#pragma once
// Descriptor pools and sets on the application's device, as the backend makes its own (frame,
// warp and pre-pass sets): layouts, a pool sized for a known set of layouts, then one set per
// layout.
// tools/byo_vulkan_example allocates its frame, warp and material sets with these, and makes and
// fills its warp set with makeWarpSetLayout / writeWarpSet.
// Thread-safety: free functions; a pool must not be used from two threads at once (Vulkan's
// external synchronization rule for vkAllocateDescriptorSets).
#include <cstdint>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "confvis/base/export.hpp"
#include "confvis/backends/vulkan/byo_upload.hpp"

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

// A set layout of `bindings`; the caller destroys it (vkDestroyDescriptorSetLayout). Throws
// Error(Internal) naming vkCreateDescriptorSetLayout where the device refuses.
VkDescriptorSetLayout makeDescriptorSetLayout(
    VkDevice device, std::span<const VkDescriptorSetLayoutBinding> bindings);

// Combined image samplers a warp set (makeWarpSetLayout) takes from its pool: the geom map and
// the coverage (ray) map.
inline constexpr std::uint32_t kWarpSetImageSamplers = 2;

// The layout of the warp set (set CONFVIS_WARP_SET) the backend's warp stages read: the geom map
// at kWarpBinding for `warpStages` (every stage that warps), the ray map at kCoverageBinding for
// the geometry stage (warp.geom moves the ends of the pieces the source's cut tears out to the
// display's rim: confvis_warp_rim.glsl). The caller destroys it. Throws Error(Internal) naming
// vkCreateDescriptorSetLayout where the device refuses.
VkDescriptorSetLayout makeWarpSetLayout(VkDevice device, VkShaderStageFlags warpStages);

// Points a warp set's two bindings at `map` (geomView() and rayView(), with map.sampler()).
void writeWarpSet(VkDevice device, VkDescriptorSet set, const UploadedRetargetMap& map);

}  // namespace vulkan
}  // namespace confvis
