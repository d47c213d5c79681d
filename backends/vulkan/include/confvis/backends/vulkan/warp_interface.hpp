#pragma once
// The conformal warp for applications' own Vulkan renderers (issue 6): the C++ half of
// shaders/confvis_warp.glsl. Create a cube-compatible image with these settings, upload
// geomMapUploadData() into its six layers, bind it with warpLayoutBinding() / warpSamplerInfo(),
// and call the GLSL functions in the shaders. The confvis Vulkan backend itself does exactly this.
// The stages that move the pieces torn by the source's cut out to the display's rim
// (shaders/confvis_warp_rim.glsl: the backend's warp.geom and conformal pre-pass) also read the
// ray map at kCoverageBinding of the same set (coverageLayoutBinding(), rayMapUploadData()).
#include <array>
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "confvis/base/export.hpp"
#include "confvis/conformal/retarget_map.hpp"

namespace confvis CONFVIS_API {
namespace vulkan CONFVIS_API {

// Defaults of CONFVIS_WARP_SET / CONFVIS_WARP_BINDING in confvis_warp.glsl.
inline constexpr std::uint32_t kWarpDescriptorSet = 1;
inline constexpr std::uint32_t kWarpBinding = 0;
// Default of CONFVIS_COVERAGE_BINDING in confvis_warp_rim.glsl: the ray map, for its alpha (where
// the display shows a physical direction; its rim is the image of the source's cut).
inline constexpr std::uint32_t kCoverageBinding = 1;
// Float32: half floats quantise directions to ~0.03 degrees, close to a CAVE pixel.
inline constexpr VkFormat kGeomMapFormat = VK_FORMAT_R32G32B32A32_SFLOAT;

// Texel data of the `geom` map's six Vulkan cube layers (faces +X, -X, +Y, -Y, +Z, -Z), each
// N x N RGBA float32, rows in order, layers back to back: one vkCmdCopyBufferToImage with six
// layers. The in-face orientation is converted (toVulkanLayout), so a samplerCube looking up a
// virtual direction v returns what RetargetMap::geom stores for v. Throws Error(InvalidInput) for
// a malformed map (wrong face sizes, non-finite texels).
std::vector<float> geomMapUploadData(const RetargetMap& map);
// The same for the `ray` map (indexed by physical direction; alpha: where the display shows it).
std::vector<float> rayMapUploadData(const RetargetMap& map);

// A combined-image-sampler binding at kWarpBinding for the given stages (every stage that warps:
// vertex, tessellation control and evaluation, geometry).
VkDescriptorSetLayoutBinding warpLayoutBinding(VkShaderStageFlags stages);

// A combined-image-sampler binding at kCoverageBinding for the given stages (those that call
// confvisSnapToRim: the geometry stage of the backend's warp.geom, the pre-pass's compute stage).
// Bind rayMapUploadData()'s image there with warpSamplerInfo()'s settings.
VkDescriptorSetLayoutBinding coverageLayoutBinding(VkShaderStageFlags stages);

// The warp set's two bindings, as the backend's warp stages read them: the geom map for
// `warpStages`, the coverage (ray) map for `rimStages`.
std::array<VkDescriptorSetLayoutBinding, 2> warpSetLayoutBindings(VkShaderStageFlags warpStages,
                                                                  VkShaderStageFlags rimStages);

// Linear filtering, clamp to edge, no mipmaps (the warp refines the blend by itself next to the
// cut, where it fetches the four texels with textureGather).
VkSamplerCreateInfo warpSamplerInfo();

}  // namespace vulkan
}  // namespace confvis
