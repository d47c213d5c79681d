#include "pipelines.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <stdint.h>  // the generated SPIR-V headers use ::uint32_t

#include "confvis/backends/vulkan/byo_descriptors.hpp"
#include "confvis/backends/vulkan/byo_pipeline.hpp"
#include "confvis/backends/vulkan/byo_prepass.hpp"
#include "confvis/backends/vulkan/warp_interface.hpp"
#include "vk_check.hpp"

// SPIR-V compiled from shaders/ by glslangValidator at build time (see CMakeLists.txt).
#include "confvis_spirv/scene_frag.h"
#include "confvis_spirv/scene_vert.h"
#include "confvis_spirv/warp_geom.h"
#include "confvis_spirv/warp_tesc.h"
#include "confvis_spirv/warp_projected_tese.h"
#include "confvis_spirv/warp_tese.h"
#include "confvis_spirv/warp_simple_vert.h"
#include "confvis_spirv/warp_vert.h"

namespace confvis::vulkan {

UniqueShaderModule shaderModule(VkDevice device, const std::uint32_t* code, std::size_t bytes) {
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = bytes;
  info.pCode = code;
  VkShaderModule module = VK_NULL_HANDLE;
  check(vkCreateShaderModule(device, &info, nullptr, &module), "vkCreateShaderModule");
  return UniqueShaderModule(device, module);
}

UniqueDescriptorSetLayout setLayout(VkDevice device,
                                    const std::vector<VkDescriptorSetLayoutBinding>& bindings) {
  return UniqueDescriptorSetLayout(device, makeDescriptorSetLayout(device, bindings));
}

UniquePipelineLayout pipelineLayout(VkDevice device, const std::vector<VkDescriptorSetLayout>& sets,
                                    const VkPushConstantRange& push) {
  VkPipelineLayoutCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  info.setLayoutCount = static_cast<std::uint32_t>(sets.size());
  info.pSetLayouts = sets.data();
  info.pushConstantRangeCount = 1;
  info.pPushConstantRanges = &push;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  check(vkCreatePipelineLayout(device, &info, nullptr, &layout), "vkCreatePipelineLayout");
  return UniquePipelineLayout(device, layout);
}

namespace {

constexpr VkShaderStageFlags kGeometryStages =
    VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT |
    VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT | VK_SHADER_STAGE_GEOMETRY_BIT;
constexpr VkShaderStageFlags kAllStages = kGeometryStages | VK_SHADER_STAGE_FRAGMENT_BIT;

}  // namespace

VkPipelineShaderStageCreateInfo shaderStage(VkShaderStageFlagBits bit,
                                            const UniqueShaderModule& module) {
  VkPipelineShaderStageCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage = bit;
  info.module = module.get();
  info.pName = "main";
  return info;
}

Pipelines::Pipelines(VulkanContext& context) : context_(context) {
  const VkDevice device = context.device();
  sceneVert_ = shaderModule(device, kSpirv_scene_vert);
  sceneFrag_ = shaderModule(device, kSpirv_scene_frag);
  warpSimpleVert_ = shaderModule(device, kSpirv_warp_simple_vert);
  warpVert_ = shaderModule(device, kSpirv_warp_vert);
  warpTesc_ = shaderModule(device, kSpirv_warp_tesc);
  warpTese_ = shaderModule(device, kSpirv_warp_tese);
  warpProjectedTese_ = shaderModule(device, kSpirv_warp_projected_tese);
  warpGeom_ = shaderModule(device, kSpirv_warp_geom);

  frameSetLayout_ = setLayout(
      device, {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, kAllStages | VK_SHADER_STAGE_COMPUTE_BIT,
                nullptr},
               // The views: also the per-wall cull of the flat list (flat_wall_cull.cpp).
               {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, kAllStages | VK_SHADER_STAGE_COMPUTE_BIT,
                nullptr},
               {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT,
                nullptr},
               // The conformal vertex shaders read their vertices themselves
               // (confvis_pulled_vertex.glsl).
               {3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr},
               {4, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr},
               {5, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr}});
  // Binding 1: the ray map, whose alpha is the display's coverage (the rim, where the pre-pass
  // and warp.geom move the ends of pieces torn by the cut; the tessellation evaluation refines
  // points next to the cut's leaves on it).
  const auto warpBindings = warpSetLayoutBindings(
      kGeometryStages | VK_SHADER_STAGE_COMPUTE_BIT,
      VK_SHADER_STAGE_GEOMETRY_BIT | VK_SHADER_STAGE_COMPUTE_BIT |
          VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT);
  warpSetLayout_ = setLayout(device, {warpBindings[0], warpBindings[1]});
  materialSetLayout_ = setLayout(device, {{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                                           VK_SHADER_STAGE_FRAGMENT_BIT, nullptr}});
  static_assert(kWarpDescriptorSet == 1, "set numbers of confvis_render_common.glsl");
  layout_ = pipelineLayout(
      device, {frameSetLayout_.get(), warpSetLayout_.get(), materialSetLayout_.get()},
      {kAllStages, 0, sizeof(PushConstants)});
  createComputePipelines();
}

const Pipelines::Pass& Pipelines::pass(std::uint32_t viewCount) {
  auto found = passes_.find(viewCount);
  if (found != passes_.end()) return found->second;
  Pass pass;
  pass.renderPass = createRenderPass(viewCount);
  pass.plain = createPipeline(pass.renderPass.get(), Kind::Plain);
  pass.conformalFlat = createPipeline(pass.renderPass.get(), Kind::ConformalFlat);
  pass.conformalTessellated = createPipeline(pass.renderPass.get(), Kind::ConformalTessellated);
  pass.conformalDropping = createPipeline(pass.renderPass.get(), Kind::ConformalDropping);
  return passes_.emplace(viewCount, std::move(pass)).first->second;
}

UniqueRenderPass Pipelines::createRenderPass(std::uint32_t viewCount) const {
  std::array<VkAttachmentDescription, 2> attachments{};
  attachments[0].format = kColorFormat;
  attachments[0].samples = VK_SAMPLE_COUNT_1_BIT;
  attachments[0].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  attachments[0].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  attachments[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  attachments[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  attachments[0].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  attachments[0].finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  attachments[1] = attachments[0];
  attachments[1].format = kDepthFormat;
  attachments[1].storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  attachments[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  const VkAttachmentReference color{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  const VkAttachmentReference depth{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &color;
  subpass.pDepthStencilAttachment = &depth;
  // Targets are reused wall after wall: order this pass after the previous pass's attachment
  // writes and readback copy, and the readback copy after this pass.
  std::array<VkSubpassDependency, 2> dependencies{};
  dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[0].dstSubpass = 0;
  dependencies[0].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                 VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT |
                                 VK_PIPELINE_STAGE_TRANSFER_BIT;
  dependencies[0].srcAccessMask =
      VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  dependencies[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                 VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                 VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
  dependencies[0].dstAccessMask =
      VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
      VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  dependencies[1].srcSubpass = 0;
  dependencies[1].dstSubpass = VK_SUBPASS_EXTERNAL;
  dependencies[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  dependencies[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  dependencies[1].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
  dependencies[1].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  // Every eye of the wall in one pass: view i renders into layer i.
  const std::uint32_t viewMask = (1u << viewCount) - 1u;
  VkRenderPassMultiviewCreateInfo multiview{VK_STRUCTURE_TYPE_RENDER_PASS_MULTIVIEW_CREATE_INFO};
  multiview.subpassCount = 1;
  multiview.pViewMasks = &viewMask;
  multiview.correlationMaskCount = 1;
  multiview.pCorrelationMasks = &viewMask;
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.pNext = &multiview;
  info.attachmentCount = static_cast<std::uint32_t>(attachments.size());
  info.pAttachments = attachments.data();
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = static_cast<std::uint32_t>(dependencies.size());
  info.pDependencies = dependencies.data();
  VkRenderPass renderPass = VK_NULL_HANDLE;
  check(vkCreateRenderPass(context_.device(), &info, nullptr, &renderPass), "vkCreateRenderPass");
  return UniqueRenderPass(context_.device(), renderPass);
}

// makeWarpPipeline describes the scene's vertices as the bring-your-own ConformalVertex.
static_assert(sizeof(Vertex) == sizeof(ConformalVertex) &&
              offsetof(Vertex, normal) == offsetof(ConformalVertex, normal) &&
              offsetof(Vertex, uv) == offsetof(ConformalVertex, uv));

UniquePipeline Pipelines::createPipeline(VkRenderPass renderPass, Kind kind) const {
  std::vector<VkPipelineShaderStageCreateInfo> stages;
  switch (kind) {
    case Kind::Plain:
      stages = {shaderStage(VK_SHADER_STAGE_VERTEX_BIT, sceneVert_)};
      break;
    case Kind::ConformalFlat:
      stages = {shaderStage(VK_SHADER_STAGE_VERTEX_BIT, warpSimpleVert_)};
      break;
    case Kind::ConformalTessellated:
      stages = {shaderStage(VK_SHADER_STAGE_VERTEX_BIT, warpVert_),
                shaderStage(VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, warpTesc_),
                shaderStage(VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, warpProjectedTese_)};
      break;
    case Kind::ConformalDropping:
      stages = {shaderStage(VK_SHADER_STAGE_VERTEX_BIT, warpVert_),
                shaderStage(VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, warpTesc_),
                shaderStage(VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, warpTese_),
                shaderStage(VK_SHADER_STAGE_GEOMETRY_BIT, warpGeom_)};
      break;
  }
  stages.push_back(shaderStage(VK_SHADER_STAGE_FRAGMENT_BIT, sceneFrag_));
  // The scene's vertices at binding 0; the flat list's warps from the pre-pass at binding 1. The
  // other conformal vertex shaders read theirs from storage buffers.
  const WarpVertexInput input = kind == Kind::Plain           ? WarpVertexInput::Vertices
                                : kind == Kind::ConformalFlat ? WarpVertexInput::VerticesAndWarps
                                                              : WarpVertexInput::None;
  const VkPipeline pipeline =
      makeWarpPipeline(context_.device(), layout_.get(), renderPass, stages, input);
  return UniquePipeline(context_.device(), pipeline);
}

FrameDescriptors allocateFrameDescriptors(VulkanContext& context, const Pipelines& pipelines) {
  const VkDevice device = context.device();
  const std::array<VkDescriptorPoolSize, 3> sizes = {{
      {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
      {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 5},
      {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 2},  // the geom and ray maps
  }};
  const std::array<VkDescriptorSetLayout, 2> layouts = {pipelines.frameSetLayout(),
                                                        pipelines.warpSetLayout()};
  FrameDescriptors made;
  made.pool = UniqueDescriptorPool(device, makeDescriptorPool(device, sizes, layouts.size()));
  const std::vector<VkDescriptorSet> sets = allocateDescriptorSets(device, made.pool.get(), layouts);
  made.frameSet = sets[0];
  made.warpSet = sets[1];
  made.frameUniforms = Buffer(context, sizeof(FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                              BufferMemory::Shared);
  writeBufferDescriptor(device, made.frameSet, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                        made.frameUniforms.get());
  return made;
}

}  // namespace confvis::vulkan
