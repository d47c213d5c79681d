#pragma once
// Shader modules (SPIR-V embedded at build time), descriptor set and pipeline layouts, render
// passes and graphics pipelines. Set 0: the frame (uniforms, per wall-and-eye views); set 1: the
// warp's geom cube map (confvis_warp.glsl); set 2: a material's base-colour texture.
#include <cstdint>
#include <map>

#include <glm/glm.hpp>

#include "context.hpp"
#include "handles.hpp"

namespace confvis::vulkan {

inline constexpr VkFormat kColorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
inline constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

// std140 uniform block `Frame` of confvis_render_common.glsl.
struct FrameUniforms {
  glm::mat4 worldToPhysical;
  glm::vec4 warpCentre;
};

// std430 element `View` of confvis_render_common.glsl.
struct ViewData {
  glm::mat4 viewProj;
  glm::vec4 eyeVirtual;
  glm::vec4 params;  // max bend error, max segment angle, min cut gap (radians), tessellate
};

// Push constant block `Push` of confvis_render_common.glsl.
struct PushConstants {
  glm::vec4 baseColorFactor;
  std::uint32_t viewBase;
  std::uint32_t hasNormals;
  std::uint32_t padding[2];
};

// Interleaved vertex as uploaded by GpuScene.
struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec2 uv;
};

class Pipelines {
 public:
  explicit Pipelines(VulkanContext& context);

  VkDescriptorSetLayout frameSetLayout() const { return frameSetLayout_.get(); }
  VkDescriptorSetLayout warpSetLayout() const { return warpSetLayout_.get(); }
  VkDescriptorSetLayout materialSetLayout() const { return materialSetLayout_.get(); }
  VkPipelineLayout layout() const { return layout_.get(); }

  // A render pass drawing `viewCount` views (multiview layers) of one wall, with its plain and
  // conformal pipelines; built on first use.
  struct Pass {
    UniqueRenderPass renderPass;
    UniquePipeline plain;
    UniquePipeline conformal;
  };
  const Pass& pass(std::uint32_t viewCount);

 private:
  UniqueRenderPass createRenderPass(std::uint32_t viewCount) const;
  UniquePipeline createPipeline(VkRenderPass renderPass, bool conformal) const;

  VulkanContext& context_;
  UniqueShaderModule sceneVert_, sceneFrag_, warpVert_, warpTesc_, warpTese_, warpGeom_;
  UniqueDescriptorSetLayout frameSetLayout_, warpSetLayout_, materialSetLayout_;
  UniquePipelineLayout layout_;
  std::map<std::uint32_t, Pass> passes_;
};

}  // namespace confvis::vulkan
