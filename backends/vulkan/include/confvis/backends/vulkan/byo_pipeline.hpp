#pragma once
// Bring-your-own Vulkan: a graphics pipeline that draws the conformal pre-pass's lists
// (byo_prepass.hpp) with the warp's stages, in the state the backend's own scene pipelines use
// (src/pipelines.cpp makes them with this function). tools/byo_vulkan_example makes its three
// pipelines (flat, tessellated, dropping) with it.
// Thread-safety: a free function; the device's objects follow Vulkan's rules.
#include <span>

#include <vulkan/vulkan.h>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {
namespace vulkan CONFVIS_API {

// What the vertex stage reads from vertex buffers.
enum class WarpVertexInput {
  None,              // nothing: the stages pull their vertices from storage buffers (warp.vert)
  Vertices,          // binding 0: ConformalVertex (position location 0, normal 1, uv 2)
  VerticesAndWarps,  // and binding 1: the warps (vec4, location 3), as warp_simple.vert reads
};

// A pipeline of `stages` (tessellated, patches of 3, where they include a tessellation control
// stage) for subpass 0 of `renderPass` with one colour attachment (RGBA written, no blending)
// and a depth attachment: reverse-Z (test GREATER, write), no culling (scenes are seen from both
// sides), filled triangles, one sample, viewport and scissor dynamic. The caller destroys it.
// Throws Error(Internal) naming vkCreateGraphicsPipelines where the device refuses.
VkPipeline makeWarpPipeline(VkDevice device, VkPipelineLayout layout, VkRenderPass renderPass,
                            std::span<const VkPipelineShaderStageCreateInfo> stages,
                            WarpVertexInput vertexInput);

}  // namespace vulkan
}  // namespace confvis
