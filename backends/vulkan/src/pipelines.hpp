#pragma once
// Shader modules (SPIR-V embedded at build time), descriptor set and pipeline layouts, render
// passes, graphics pipelines and the conformal pre-pass compute pipelines. Set 0: the frame
// (uniforms, per wall-and-eye views); set 1: the warp's geom cube map (confvis_warp.glsl);
// set 2: a material's base-colour texture (graphics) or the pre-pass buffers (compute).
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "context.hpp"
#include "handles.hpp"
#include "memory.hpp"

namespace confvis::vulkan {

inline constexpr VkFormat kColorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
inline constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

// std140 uniform block `Frame` of confvis_render_common.glsl.
struct FrameUniforms {
  glm::mat4 worldToPhysical;
  glm::vec4 warpCentre;
  bool operator==(const FrameUniforms&) const = default;
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
  std::int32_t vertexOffset;   // tessellated draws: the mesh's (warp.vert reads the indices)
};

// Set 2 of confvis_prepass_common.glsl: storage buffers, one uniform buffer
// (kPrepassErrorWallsBinding), then from kPrepassFirstTexelBinding on uniform texel buffers
// (PrepassTexels).
inline constexpr std::uint32_t kPrepassFirstTexelBinding = 25;
// The texel buffer views, in binding order: what the passes over every vertex, edge and triangle
// read. Lavapipe gathers a texel fetch for all SIMD lanes at once but loads from a storage buffer
// lane by lane (the two warps an edge reads: 6 ms of a 1M-triangle edge pass as storage, 1 ms
// as texels).
enum class PrepassTexels : std::uint32_t {
  Vertices,       // the scene's vertices as RGBA32F, two texels each (position, normal, uv)
  Relative,       // the pre-pass's virtual points relative to c
  Warped,         // their warps (the scene vertices' part)
  Edges,          // RG32UI: the distinct edges' vertex pairs
  Indices,        // R32UI: the scene's index buffer
  TriangleEdges,  // R32UI: each triangle's edges
  EdgeFlags,      // R32UI: the pre-pass's edge flags
  Count
};
inline constexpr std::uint32_t kPrepassBindings =
    kPrepassFirstTexelBinding + static_cast<std::uint32_t>(PrepassTexels::Count);
// Those bound to parts of the scene's vertex buffer and of the warps (GpuScene's layout).
inline constexpr std::uint32_t kPrepassVerticesBinding = 0;
inline constexpr std::uint32_t kPrepassWarpedBinding = 2;
inline constexpr std::uint32_t kPrepassEdgeLevelsBinding = 8;
inline constexpr std::uint32_t kPrepassCutAttributesBinding = 21;
inline constexpr std::uint32_t kPrepassCutWarpsBinding = 22;
inline constexpr std::uint32_t kPrepassErrorWallsBinding = 24;  // a uniform buffer
// Walls the uniform buffer holds (std140 ErrorWall[64], 4 KB); frames with more use the
// strictest bound everywhere.
inline constexpr std::uint32_t kMaxErrorWalls = 64;

// Push constant block `Prepass` of confvis_prepass_common.glsl.
struct PrepassConstants {
  std::uint32_t count;
  std::uint32_t mesh;
  std::uint32_t firstIndex;
  std::int32_t vertexOffset;
  float maxErrorAngle;
  float maxSegmentAngle;
  float minGap;
  std::uint32_t midpointBase;   // GpuScene::midpointBase()
  float maxGap;
  std::uint32_t splitAlongCut;  // 0 or 1
  std::uint32_t cutVertexBase;  // GpuScene::cutVertexBase()
  std::uint32_t errorWallCount;  // ErrorWall entries in use (at most kMaxErrorWalls)
  std::uint32_t snapCutToRim;    // 0 or 1
  std::uint32_t dropOutside;     // 0 or 1: VulkanOptions::dropOutsideSourceField
};

// std430 element `ErrorWall` of confvis_prepass_common.glsl: a wall's lit rectangle relative to
// the warp centre c and the bend error it tolerates, errorPixels of its pixels.
struct ErrorWall {
  glm::vec4 lowerLeft;  // xyz relative to c; w: errorPixels * pixel pitch / distance of the plane
  glm::vec4 right;      // xyz unit; w: width, metres
  glm::vec4 up;         // xyz unit; w: height, metres
  glm::vec4 normal;     // xyz unit, towards c; w: distance of the plane from c
  bool operator==(const ErrorWall&) const = default;
};

// Interleaved vertex as uploaded by GpuScene.
struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec2 uv;
};

UniqueShaderModule shaderModule(VkDevice device, const std::uint32_t* code, std::size_t bytes);
template <std::size_t N>
UniqueShaderModule shaderModule(VkDevice device, const std::uint32_t (&spirv)[N]) {
  return shaderModule(device, spirv, sizeof(spirv));
}
VkPipelineShaderStageCreateInfo shaderStage(VkShaderStageFlagBits bit,
                                            const UniqueShaderModule& module);
UniqueDescriptorSetLayout setLayout(VkDevice device,
                                    const std::vector<VkDescriptorSetLayoutBinding>& bindings);
UniquePipelineLayout pipelineLayout(VkDevice device, const std::vector<VkDescriptorSetLayout>& sets,
                                    const VkPushConstantRange& push);
// `count` storage buffers at bindings 0 .. count - 1 for a compute pass (pipelines_compute.cpp).
UniqueDescriptorSetLayout computeBuffersSetLayout(VkDevice device, std::uint32_t count);
// A compute pipeline of `module`'s main (pipelines_compute.cpp).
UniquePipeline computePipeline(VkDevice device, VkPipelineLayout layout,
                               const UniqueShaderModule& module);

class Pipelines {
 public:
  explicit Pipelines(VulkanContext& context);

  VkDescriptorSetLayout frameSetLayout() const { return frameSetLayout_.get(); }
  VkDescriptorSetLayout warpSetLayout() const { return warpSetLayout_.get(); }
  VkDescriptorSetLayout materialSetLayout() const { return materialSetLayout_.get(); }
  VkDescriptorSetLayout prepassSetLayout() const { return prepassSetLayout_.get(); }
  VkPipelineLayout layout() const { return layout_.get(); }
  VkPipelineLayout computeLayout() const { return computeLayout_.get(); }
  VkPipeline warpVertices() const { return warpVertices_.get(); }
  VkPipeline warpVerticesAcrossCut() const { return warpVerticesAcrossCut_.get(); }
  VkPipeline classifyEdges() const { return classifyEdges_.get(); }
  VkPipeline classifyEdgesBent() const { return classifyEdgesBent_.get(); }
  VkPipeline classifyEdgesAtCut() const { return classifyEdgesAtCut_.get(); }
  VkPipeline classifyTriangles() const { return classifyTriangles_.get(); }
  VkPipeline classifyStraightTriangles() const { return classifyStraightTriangles_.get(); }
  VkPipeline classifyBentTriangles() const { return classifyBentTriangles_.get(); }
  VkPipeline splitTrianglesAtCut() const { return splitTrianglesAtCut_.get(); }

  // A render pass drawing `viewCount` views (multiview layers) of one wall, with its pipelines;
  // built on first use. Conformal mode draws with three, for the pre-pass's lists:
  // conformalFlat for the triangles it found straight enough and the flat pieces of those it
  // split, conformalTessellated (tessellation) for the bent ones and conformalDropping
  // (tessellation + the geometry shader that drops pieces) for those on the cut, at the source's
  // rim or strongly distorted.
  struct Pass {
    UniqueRenderPass renderPass;
    UniquePipeline plain;
    UniquePipeline conformalFlat;
    UniquePipeline conformalTessellated;
    UniquePipeline conformalDropping;
    // The tessellated lists as captured once a frame (warp_capture.hpp): made by
    // capturedDraw() on first use.
    UniquePipeline conformalCaptured;
  };
  const Pass& pass(std::uint32_t viewCount);
  // Pass(viewCount)'s conformalCaptured (pipelines_capture.cpp), made on first use: frames that
  // capture nothing (plain ones, `confvis view --mode plain`) do not wait for its compilation.
  VkPipeline capturedDraw(std::uint32_t viewCount);

  // The once-a-frame capture (pipelines_capture.cpp; the device must have transform feedback,
  // VulkanContext::transformFeedback): a render pass without attachments and the tessellated
  // lists' pipelines writing their triangles by transform feedback, nothing rasterized.
  struct Capture {
    UniqueRenderPass renderPass;
    UniqueFramebuffer framebuffer;  // 1 x 1, no attachments
    UniquePipeline tessellated, dropping;
  };
  const Capture& capture();

 private:
  enum class Kind { Plain, ConformalFlat, ConformalTessellated, ConformalDropping };
  UniquePipeline createCapturedDrawPipeline(VkRenderPass renderPass);  // pipelines_capture.cpp
  UniqueRenderPass createRenderPass(std::uint32_t viewCount) const;
  UniquePipeline createPipeline(VkRenderPass renderPass, Kind kind) const;
  void createComputePipelines();  // pipelines_compute.cpp

  VulkanContext& context_;
  UniqueShaderModule sceneVert_, sceneFrag_, warpSimpleVert_, warpVert_, warpTesc_, warpTese_,
      warpProjectedTese_, warpGeom_, warpCapturedVert_, warpProjectedTeseCapture_,
      warpGeomCapture_;
  UniqueDescriptorSetLayout frameSetLayout_, warpSetLayout_, materialSetLayout_,
      prepassSetLayout_;
  UniquePipelineLayout layout_, computeLayout_;
  UniquePipeline warpVertices_, warpVerticesAcrossCut_, classifyEdges_, classifyEdgesBent_,
      classifyEdgesAtCut_, classifyTriangles_, classifyStraightTriangles_, classifyBentTriangles_,
      splitTrianglesAtCut_;
  std::map<std::uint32_t, Pass> passes_;
  std::optional<Capture> capture_;
};

// The two sets every warped draw and the pre-pass bind (the frame's uniforms, storage buffers and
// the warp's maps), allocated from a pool of their own, with the frame uniform buffer written to
// binding 0 of the frame set. The backend's frame renderer and the application's pre-pass step
// (byo_prepass.cpp) each hold one.
struct FrameDescriptors {
  UniqueDescriptorPool pool;
  VkDescriptorSet frameSet = VK_NULL_HANDLE, warpSet = VK_NULL_HANDLE;
  Buffer frameUniforms;
};
FrameDescriptors allocateFrameDescriptors(VulkanContext& context, const Pipelines& pipelines);

}  // namespace confvis::vulkan
