#include "app_pipelines.hpp"

#include <array>
#include <cstdint>
#include <vector>

#include "app_device.hpp"
#include "confvis/backends/vulkan/byo_descriptors.hpp"
#include "confvis/backends/vulkan/byo_pipeline.hpp"
#include "confvis/backends/vulkan/byo_prepass.hpp"
#include "confvis/backends/vulkan/warp_interface.hpp"

// SPIR-V the application compiled (CMakeLists.txt: glslangValidator -I<confvis shader dir>).
#include "byo_spirv/scene_frag.h"
#include "byo_spirv/warp_geom.h"
#include "byo_spirv/warp_projected_tese.h"
#include "byo_spirv/warp_simple_vert.h"
#include "byo_spirv/warp_tesc.h"
#include "byo_spirv/warp_tese.h"
#include "byo_spirv/warp_vert.h"

namespace byo_example {
namespace {

constexpr VkShaderStageFlags kGeometryStages =
    VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT |
    VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT | VK_SHADER_STAGE_GEOMETRY_BIT;
constexpr VkShaderStageFlags kAllStages = kGeometryStages | VK_SHADER_STAGE_FRAGMENT_BIT;

template <std::size_t N>
VkShaderModule shaderModule(VkDevice device, const std::uint32_t (&spirv)[N]) {
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = sizeof(spirv);
  info.pCode = spirv;
  VkShaderModule module = VK_NULL_HANDLE;
  vkCheck(vkCreateShaderModule(device, &info, nullptr, &module), "vkCreateShaderModule");
  return module;
}

VkRenderPass createRenderPass(VkDevice device) {
  std::array<VkAttachmentDescription, 2> attachments{};
  attachments[0].format = kAppColorFormat;
  attachments[0].samples = VK_SAMPLE_COUNT_1_BIT;
  attachments[0].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  attachments[0].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  attachments[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  attachments[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  attachments[0].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  attachments[0].finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;  // read back after the pass
  attachments[1] = attachments[0];
  attachments[1].format = kAppDepthFormat;
  attachments[1].storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  attachments[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  const VkAttachmentReference color{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  const VkAttachmentReference depth{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &color;
  subpass.pDepthStencilAttachment = &depth;
  // The copy for readback waits for the pass's colour writes.
  VkSubpassDependency toCopy{};
  toCopy.srcSubpass = 0;
  toCopy.dstSubpass = VK_SUBPASS_EXTERNAL;
  toCopy.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  toCopy.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  toCopy.dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
  toCopy.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = static_cast<std::uint32_t>(attachments.size());
  info.pAttachments = attachments.data();
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 1;
  info.pDependencies = &toCopy;
  VkRenderPass renderPass = VK_NULL_HANDLE;
  vkCheck(vkCreateRenderPass(device, &info, nullptr, &renderPass), "vkCreateRenderPass");
  return renderPass;
}

VkPipelineShaderStageCreateInfo stage(VkShaderStageFlagBits bit, VkShaderModule module) {
  VkPipelineShaderStageCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage = bit;
  info.module = module;
  info.pName = "main";
  return info;
}
}  // namespace

AppPipelines::AppPipelines(VkDevice device) : device_(device) {
  // Set 0: what confvis_render_common.glsl and confvis_pulled_vertex.glsl declare.
  using Bindings = std::vector<VkDescriptorSetLayoutBinding>;
  setLayouts_[0] = confvis::vulkan::makeDescriptorSetLayout(
      device, Bindings{{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, kAllStages, nullptr},
               {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, kAllStages, nullptr},
               {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT,
                nullptr},
               {3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr},
               {4, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr},
               {5, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr}});
  // Set 1: the warp (confvis_warp.glsl, and the rim's coverage map that warp.geom reads:
  // confvis_warp_rim.glsl), as warp_interface.hpp describes it.
  setLayouts_[1] = confvis::vulkan::makeWarpSetLayout(device, kGeometryStages);
  setLayouts_[2] = confvis::vulkan::makeDescriptorSetLayout(
      device, Bindings{{0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                        VK_SHADER_STAGE_FRAGMENT_BIT, nullptr}});
  const VkPushConstantRange push{kAllStages, 0, sizeof(AppPush)};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = 3;
  layoutInfo.pSetLayouts = setLayouts_;
  layoutInfo.pushConstantRangeCount = 1;
  layoutInfo.pPushConstantRanges = &push;
  vkCheck(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &layout_), "vkCreatePipelineLayout");
  renderPass_ = createRenderPass(device);

  const VkShaderModule modules[] = {
      shaderModule(device, kAppSpirv_warp_simple_vert), shaderModule(device, kAppSpirv_warp_vert),
      shaderModule(device, kAppSpirv_warp_tesc), shaderModule(device, kAppSpirv_warp_projected_tese),
      shaderModule(device, kAppSpirv_warp_tese), shaderModule(device, kAppSpirv_warp_geom),
      shaderModule(device, kAppSpirv_scene_frag)};
  const auto [simpleVert, warpVert, tesc, projectedTese, tese, geom, frag] = modules;
  // The pre-pass's lists, drawn as the backend draws them (makeWarpPipeline's state). Flat:
  // vertex input from the step's vertex buffer (binding 0, ConformalVertex) and its warps
  // (binding 1); tessellated: no vertex input (warp.vert reads the lists itself), patches of 3.
  using confvis::vulkan::makeWarpPipeline;
  using confvis::vulkan::WarpVertexInput;
  const VkPipelineShaderStageCreateInfo flatStages[] = {
      stage(VK_SHADER_STAGE_VERTEX_BIT, simpleVert), stage(VK_SHADER_STAGE_FRAGMENT_BIT, frag)};
  const VkPipelineShaderStageCreateInfo tessellatedStages[] = {
      stage(VK_SHADER_STAGE_VERTEX_BIT, warpVert),
      stage(VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, tesc),
      stage(VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, projectedTese),
      stage(VK_SHADER_STAGE_FRAGMENT_BIT, frag)};
  const VkPipelineShaderStageCreateInfo droppingStages[] = {
      stage(VK_SHADER_STAGE_VERTEX_BIT, warpVert),
      stage(VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, tesc),
      stage(VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, tese),
      stage(VK_SHADER_STAGE_GEOMETRY_BIT, geom), stage(VK_SHADER_STAGE_FRAGMENT_BIT, frag)};
  flat_ = makeWarpPipeline(device, layout_, renderPass_, flatStages,
                           WarpVertexInput::VerticesAndWarps);
  tessellated_ = makeWarpPipeline(device, layout_, renderPass_, tessellatedStages,
                                  WarpVertexInput::None);
  dropping_ = makeWarpPipeline(device, layout_, renderPass_, droppingStages, WarpVertexInput::None);
  for (VkShaderModule module : modules) vkDestroyShaderModule(device, module, nullptr);
}

AppPipelines::~AppPipelines() {
  for (VkPipeline pipeline : {flat_, tessellated_, dropping_})
    if (pipeline) vkDestroyPipeline(device_, pipeline, nullptr);
  if (renderPass_) vkDestroyRenderPass(device_, renderPass_, nullptr);
  if (layout_) vkDestroyPipelineLayout(device_, layout_, nullptr);
  for (VkDescriptorSetLayout layout : setLayouts_)
    if (layout) vkDestroyDescriptorSetLayout(device_, layout, nullptr);
}

}  // namespace byo_example
