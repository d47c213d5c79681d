#pragma once
// The graphics pipeline every confvis draw uses (byo_pipeline.cpp; makeWarpPipeline describes
// its vertex input by WarpVertexInput): two-sided, reverse-Z depth, one colour attachment,
// dynamic viewport and scissor, patches of 3 where the stages tessellate. rasterizerDiscard:
// the once-a-frame capture's pipelines (transform feedback only, a render pass without
// attachments).
#include <span>

#include <vulkan/vulkan.h>

namespace confvis::vulkan {

VkPipeline makeGraphicsPipeline(VkDevice device, VkPipelineLayout layout, VkRenderPass renderPass,
                                std::span<const VkPipelineShaderStageCreateInfo> stages,
                                const VkPipelineVertexInputStateCreateInfo& input,
                                bool rasterizerDiscard = false);

}  // namespace confvis::vulkan
