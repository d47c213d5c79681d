// The once-a-frame capture's render pass and pipelines (pipelines.hpp, warp_capture.hpp).
#include <array>

#include <stdint.h>  // the generated SPIR-V headers use ::uint32_t

#include "graphics_pipeline.hpp"
#include "pipelines.hpp"
#include "vk_check.hpp"
#include "warp_capture.hpp"

#include "confvis_spirv/warp_captured_vert.h"
#include "confvis_spirv/warp_geom_capture.h"
#include "confvis_spirv/warp_projected_tese_capture.h"

namespace confvis::vulkan {

UniquePipeline Pipelines::createCapturedDrawPipeline(VkRenderPass renderPass) {
  if (!warpCapturedVert_)  // made on first use, as the passes are
    warpCapturedVert_ = shaderModule(context_.device(), kSpirv_warp_captured_vert);
  const std::array<VkPipelineShaderStageCreateInfo, 2> stages = {
      shaderStage(VK_SHADER_STAGE_VERTEX_BIT, warpCapturedVert_),
      shaderStage(VK_SHADER_STAGE_FRAGMENT_BIT, sceneFrag_)};
  const VkVertexInputBindingDescription binding{0, sizeof(CapturedVertex),
                                                VK_VERTEX_INPUT_RATE_VERTEX};
  const std::array<VkVertexInputAttributeDescription, 4> attributes = {{
      {0, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(CapturedVertex, physical)},
      {1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(CapturedVertex, world)},
      {2, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(CapturedVertex, normal)},
      {3, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(CapturedVertex, uv)},
  }};
  VkPipelineVertexInputStateCreateInfo input{
      VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  input.vertexBindingDescriptionCount = 1;
  input.pVertexBindingDescriptions = &binding;
  input.vertexAttributeDescriptionCount = static_cast<std::uint32_t>(attributes.size());
  input.pVertexAttributeDescriptions = attributes.data();
  return UniquePipeline(context_.device(), makeGraphicsPipeline(context_.device(), layout_.get(),
                                                                renderPass, stages, input));
}

VkPipeline Pipelines::capturedDraw(std::uint32_t viewCount) {
  pass(viewCount);
  Pass& made = passes_.at(viewCount);
  if (!made.conformalCaptured)
    made.conformalCaptured = createCapturedDrawPipeline(made.renderPass.get());
  return made.conformalCaptured.get();
}

const Pipelines::Capture& Pipelines::capture() {
  if (capture_) return *capture_;
  const VkDevice device = context_.device();
  Capture made;
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  VkRenderPass renderPass = VK_NULL_HANDLE;
  check(vkCreateRenderPass(device, &info, nullptr, &renderPass), "vkCreateRenderPass");
  made.renderPass = UniqueRenderPass(device, renderPass);
  VkFramebufferCreateInfo framebufferInfo{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  framebufferInfo.renderPass = renderPass;
  framebufferInfo.width = framebufferInfo.height = framebufferInfo.layers = 1;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  check(vkCreateFramebuffer(device, &framebufferInfo, nullptr, &framebuffer),
        "vkCreateFramebuffer");
  made.framebuffer = UniqueFramebuffer(device, framebuffer);
  warpProjectedTeseCapture_ = shaderModule(device, kSpirv_warp_projected_tese_capture);
  warpGeomCapture_ = shaderModule(device, kSpirv_warp_geom_capture);
  const VkPipelineVertexInputStateCreateInfo noInput{
      VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};  // warp.vert pulls its own
  const std::array<VkPipelineShaderStageCreateInfo, 3> tessellated = {
      shaderStage(VK_SHADER_STAGE_VERTEX_BIT, warpVert_),
      shaderStage(VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, warpTesc_),
      shaderStage(VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, warpProjectedTeseCapture_)};
  const std::array<VkPipelineShaderStageCreateInfo, 4> dropping = {
      shaderStage(VK_SHADER_STAGE_VERTEX_BIT, warpVert_),
      shaderStage(VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, warpTesc_),
      shaderStage(VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, warpTese_),
      shaderStage(VK_SHADER_STAGE_GEOMETRY_BIT, warpGeomCapture_)};
  made.tessellated = UniquePipeline(
      device, makeGraphicsPipeline(device, layout_.get(), renderPass, tessellated, noInput, true));
  made.dropping = UniquePipeline(
      device, makeGraphicsPipeline(device, layout_.get(), renderPass, dropping, noInput, true));
  capture_ = std::move(made);
  return *capture_;
}

}  // namespace confvis::vulkan
