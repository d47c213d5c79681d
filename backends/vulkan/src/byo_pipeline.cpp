#include "confvis/backends/vulkan/byo_pipeline.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#include "confvis/backends/vulkan/byo_prepass.hpp"
#include "graphics_pipeline.hpp"
#include "vk_check.hpp"

namespace confvis::vulkan {

VkPipeline makeWarpPipeline(VkDevice device, VkPipelineLayout layout, VkRenderPass renderPass,
                            std::span<const VkPipelineShaderStageCreateInfo> stages,
                            WarpVertexInput vertexInput) {
  const std::array<VkVertexInputBindingDescription, 2> bindings = {{
      {0, sizeof(ConformalVertex), VK_VERTEX_INPUT_RATE_VERTEX},
      {1, sizeof(glm::vec4), VK_VERTEX_INPUT_RATE_VERTEX},
  }};
  const std::array<VkVertexInputAttributeDescription, 4> attributes = {{
      {0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(ConformalVertex, position)},
      {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(ConformalVertex, normal)},
      {2, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(ConformalVertex, uv)},
      {3, 1, VK_FORMAT_R32G32B32A32_SFLOAT, 0},
  }};
  VkPipelineVertexInputStateCreateInfo input{
      VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  if (vertexInput != WarpVertexInput::None) {
    const bool warps = vertexInput == WarpVertexInput::VerticesAndWarps;
    input.vertexBindingDescriptionCount = warps ? 2 : 1;
    input.pVertexBindingDescriptions = bindings.data();
    input.vertexAttributeDescriptionCount = warps ? 4 : 3;
    input.pVertexAttributeDescriptions = attributes.data();
  }
  return makeGraphicsPipeline(device, layout, renderPass, stages, input);
}

VkPipeline makeGraphicsPipeline(VkDevice device, VkPipelineLayout layout, VkRenderPass renderPass,
                                std::span<const VkPipelineShaderStageCreateInfo> stages,
                                const VkPipelineVertexInputStateCreateInfo& input,
                                bool rasterizerDiscard) {
  const bool tessellated =
      std::any_of(stages.begin(), stages.end(), [](const VkPipelineShaderStageCreateInfo& s) {
        return s.stage == VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT;
      });
  VkPipelineInputAssemblyStateCreateInfo assembly{
      VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology =
      tessellated ? VK_PRIMITIVE_TOPOLOGY_PATCH_LIST : VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkPipelineTessellationStateCreateInfo tessellation{
      VK_STRUCTURE_TYPE_PIPELINE_TESSELLATION_STATE_CREATE_INFO};
  tessellation.patchControlPoints = 3;
  VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;
  VkPipelineRasterizationStateCreateInfo raster{
      VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;  // two-sided: scenes are seen from inside and outside
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;
  raster.rasterizerDiscardEnable = rasterizerDiscard ? VK_TRUE : VK_FALSE;
  VkPipelineMultisampleStateCreateInfo multisample{
      VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineDepthStencilStateCreateInfo depth{
      VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depth.depthTestEnable = VK_TRUE;
  depth.depthWriteEnable = VK_TRUE;
  depth.depthCompareOp = VK_COMPARE_OP_GREATER;  // reverse-Z (wallViewProjection, byo_frame.hpp)
  VkPipelineColorBlendAttachmentState blendAttachment{};
  blendAttachment.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                                   VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  VkPipelineColorBlendStateCreateInfo blend{
      VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blend.attachmentCount = 1;
  blend.pAttachments = &blendAttachment;
  const std::array<VkDynamicState, 2> dynamicStates = {VK_DYNAMIC_STATE_VIEWPORT,
                                                       VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
  dynamic.dynamicStateCount = static_cast<std::uint32_t>(dynamicStates.size());
  dynamic.pDynamicStates = dynamicStates.data();

  VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  info.stageCount = static_cast<std::uint32_t>(stages.size());
  info.pStages = stages.data();
  info.pVertexInputState = &input;
  info.pInputAssemblyState = &assembly;
  info.pTessellationState = tessellated ? &tessellation : nullptr;
  info.pRasterizationState = &raster;
  if (!rasterizerDiscard) {  // else ignored (and the capture's render pass has no attachments)
    info.pViewportState = &viewport;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depth;
    info.pColorBlendState = &blend;
  }
  info.pDynamicState = rasterizerDiscard ? nullptr : &dynamic;
  info.layout = layout;
  info.renderPass = renderPass;
  info.subpass = 0;
  VkPipeline pipeline = VK_NULL_HANDLE;
  check(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline),
        "vkCreateGraphicsPipelines");
  return pipeline;
}

}  // namespace confvis::vulkan
