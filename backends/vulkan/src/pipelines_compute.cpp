// The conformal pre-pass compute pipelines (warp_vertices.comp, warp_vertices_across_cut.comp,
// classify_edges.comp, classify_edges_bent.comp, classify_edges_at_cut.comp,
// classify_triangles.comp, classify_straight_triangles.comp, classify_bent_triangles.comp,
// split_triangles_at_cut.comp) and
// their layout: set 0 the frame, set 1 the warp map, set 2 the pre-pass buffers.
#include <stdint.h>  // the generated SPIR-V headers use ::uint32_t

#include "pipelines.hpp"
#include "vk_check.hpp"

#include "confvis_spirv/classify_bent_triangles_comp.h"
#include "confvis_spirv/classify_edges_at_cut_comp.h"
#include "confvis_spirv/classify_edges_bent_comp.h"
#include "confvis_spirv/classify_edges_comp.h"
#include "confvis_spirv/classify_straight_triangles_comp.h"
#include "confvis_spirv/classify_triangles_comp.h"
#include "confvis_spirv/split_triangles_at_cut_comp.h"
#include "confvis_spirv/warp_vertices_across_cut_comp.h"
#include "confvis_spirv/warp_vertices_comp.h"

namespace confvis::vulkan {

UniqueDescriptorSetLayout computeBuffersSetLayout(VkDevice device, std::uint32_t count) {
  std::vector<VkDescriptorSetLayoutBinding> bindings;
  for (std::uint32_t binding = 0; binding < count; ++binding)
    bindings.push_back({binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
                        VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
  return setLayout(device, bindings);
}

UniquePipeline computePipeline(VkDevice device, VkPipelineLayout layout,
                               const UniqueShaderModule& module) {
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module.get();
  info.stage.pName = "main";
  info.layout = layout;
  VkPipeline pipeline = VK_NULL_HANDLE;
  check(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline),
        "vkCreateComputePipelines");
  return UniquePipeline(device, pipeline);
}

void Pipelines::createComputePipelines() {
  const VkDevice device = context_.device();
  std::vector<VkDescriptorSetLayoutBinding> buffers;
  for (std::uint32_t binding = 0; binding < kPrepassBindings; ++binding) {
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    if (binding == kPrepassErrorWallsBinding) type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    if (binding >= kPrepassFirstTexelBinding) type = VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
    buffers.push_back({binding, type, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
  }
  prepassSetLayout_ = setLayout(device, buffers);
  computeLayout_ = pipelineLayout(
      device, {frameSetLayout_.get(), warpSetLayout_.get(), prepassSetLayout_.get()},
      {VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(PrepassConstants)});
  const VkPipelineLayout layout = computeLayout_.get();
  const UniqueShaderModule warp = shaderModule(device, kSpirv_warp_vertices_comp);
  const UniqueShaderModule warpAcrossCut =
      shaderModule(device, kSpirv_warp_vertices_across_cut_comp);
  const UniqueShaderModule edges = shaderModule(device, kSpirv_classify_edges_comp);
  const UniqueShaderModule edgesBent =
      shaderModule(device, kSpirv_classify_edges_bent_comp);
  const UniqueShaderModule classify = shaderModule(device, kSpirv_classify_triangles_comp);
  warpVertices_ = computePipeline(device, layout, warp);
  warpVerticesAcrossCut_ = computePipeline(device, layout, warpAcrossCut);
  classifyEdges_ = computePipeline(device, layout, edges);
  classifyEdgesBent_ = computePipeline(device, layout, edgesBent);
  const UniqueShaderModule edgesAtCut = shaderModule(device, kSpirv_classify_edges_at_cut_comp);
  classifyEdgesAtCut_ = computePipeline(device, layout, edgesAtCut);
  classifyTriangles_ = computePipeline(device, layout, classify);
  const UniqueShaderModule bent = shaderModule(device, kSpirv_classify_bent_triangles_comp);
  classifyBentTriangles_ = computePipeline(device, layout, bent);
  const UniqueShaderModule straight = shaderModule(device, kSpirv_classify_straight_triangles_comp);
  classifyStraightTriangles_ = computePipeline(device, layout, straight);
  const UniqueShaderModule atCut = shaderModule(device, kSpirv_split_triangles_at_cut_comp);
  splitTrianglesAtCut_ = computePipeline(device, layout, atCut);
}

}  // namespace confvis::vulkan
