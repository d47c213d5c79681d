#pragma once
// The example application's own render pass, descriptor set layouts and pipelines for the
// confvis warp stages (compiled by the application from the installed shaders): set 0 the frame
// (Frame uniform, Views, and the pre-pass step's patch levels, tessellated indices, vertices and
// warps), set 1 the warp's geom map (CONFVIS_WARP_SET / CONFVIS_WARP_BINDING), set 2 a material's
// texture; the push constants of confvis_render_common.glsl.
#include <cstdint>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

namespace byo_example {

inline constexpr VkFormat kAppColorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
inline constexpr VkFormat kAppDepthFormat = VK_FORMAT_D32_SFLOAT;

// The shaders' `Push` block.
struct AppPush {
  glm::vec4 baseColorFactor;
  std::uint32_t viewBase;
  std::uint32_t hasNormals;
  std::int32_t vertexOffset;
};

// The shaders' `View` (std430) and `Frame` (std140) blocks.
struct AppView {
  glm::mat4 viewProj;
  glm::vec4 eyeVirtual;
  glm::vec4 params;  // the wall's WallWarpBounds: error, segment, cut gap (radians); 1 = tessellate
};
struct AppFrame {
  glm::mat4 worldToPhysical;
  glm::vec4 warpCentre;
};

class AppPipelines {
 public:
  explicit AppPipelines(VkDevice device);
  ~AppPipelines();
  AppPipelines(const AppPipelines&) = delete;
  AppPipelines& operator=(const AppPipelines&) = delete;

  VkRenderPass renderPass() const { return renderPass_; }
  VkPipelineLayout layout() const { return layout_; }
  VkDescriptorSetLayout frameSetLayout() const { return setLayouts_[0]; }
  VkDescriptorSetLayout warpSetLayout() const { return setLayouts_[1]; }
  VkDescriptorSetLayout materialSetLayout() const { return setLayouts_[2]; }
  VkPipeline flat() const { return flat_; }                // Flat and Pieces lists
  VkPipeline tessellated() const { return tessellated_; }  // Tessellated list
  VkPipeline dropping() const { return dropping_; }        // Dropping list

 private:
  VkDevice device_;
  VkDescriptorSetLayout setLayouts_[3] = {};
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkRenderPass renderPass_ = VK_NULL_HANDLE;
  VkPipeline flat_ = VK_NULL_HANDLE, tessellated_ = VK_NULL_HANDLE, dropping_ = VK_NULL_HANDLE;
};

}  // namespace byo_example
