#pragma once
// The once-a-frame warp (issue 23): the pre-pass's tessellated lists (the bent triangles and
// those the geometry shader splits at the cut) depend on the wall only through its projection,
// so they are tessellated, warped and split once a frame, their triangles written by transform
// feedback (VK_EXT_transform_feedback, nothing rasterized) as warped physical points with their
// attributes, and every wall and eye draws that buffer with a plain vertex shader
// (warp_captured.vert) and its own projection; the hardware clips per wall as before. Before,
// every wall's draw redid the tessellation and the ~22 full map lookups of each torn piece's
// split (shaders/confvis_warp_capture.glsl has the record's layout).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "captured_cut_split.hpp"
#include "conformal_prepass.hpp"
#include "gpu_scene.hpp"
#include "gpu_stopwatch.hpp"
#include "memory.hpp"
#include "pipelines.hpp"

namespace confvis::vulkan {

// One captured vertex (confvis_warp_capture.glsl): c + T(x - c) with w = 1, then the attributes.
struct CapturedVertex {
  glm::vec4 physical;
  glm::vec3 world;
  glm::vec3 normal;
  glm::vec2 uv;
};
static_assert(sizeof(CapturedVertex) == 48, "xfb_stride of confvis_warp_capture.glsl");

class WarpCapture {
 public:
  // The context must have transform feedback (VulkanContext::transformFeedback).
  WarpCapture(VulkanContext& context, Pipelines& pipelines);

  // Captures the Tessellated and Dropping lists of every mesh of `scene` as the completed
  // pre-pass left them, drawn through view `captureView` of the frame set's views (an identity
  // viewProj, params.w above 4: warp.tesc culls by no view). Each list's region is sized from
  // the previous capture's needs (at first a share per patch); a region that overflows (the
  // transform-feedback query's primitives needed above those written) grows to its need and the
  // capture runs again, so no triangle is silently dropped. The Dropping list's torn pieces
  // are split in compute after it (captured_cut_split.hpp; not where `splitTornPieces` is false,
  // a broken render for tests), their ends moved out to the rim where `snapToRim`
  // (VulkanOptions::snapCutToRim). Returns the GPU time (nullopt without timestamps).
  std::optional<double> capture(const GpuScene& scene, const ConformalPrepass& prepass,
                                VkDescriptorSet frameSet, VkDescriptorSet warpSet,
                                std::uint32_t captureView, bool snapToRim,
                                bool splitTornPieces, GpuStopwatch& stopwatch);

  struct Range {
    std::uint32_t firstVertex = 0, vertexCount = 0;
  };
  // Where mesh `draw`'s captured list lies in buffer() (list: Tessellated or Dropping).
  Range range(std::size_t draw, PrepassList list) const;
  VkBuffer buffer() const { return buffer_.get(); }
  // Captures run since construction, including the reruns after an overflow (for tests).
  std::size_t captures() const { return captures_; }
  // The torn pieces the last capture split in compute (for tests).
  std::uint32_t tornPieces() const { return split_->tornPieces(); }

 private:
  static std::size_t region(std::size_t draw, PrepassList list);
  void record(VkCommandBuffer cmd, const GpuScene& scene, const ConformalPrepass& prepass,
              VkDescriptorSet frameSet, VkDescriptorSet warpSet, std::uint32_t captureView,
              bool snapToRim, bool splitTornPieces);

  VulkanContext& context_;
  Pipelines& pipelines_;
  PFN_vkCmdBindTransformFeedbackBuffersEXT bindBuffers_ = nullptr;
  PFN_vkCmdBeginTransformFeedbackEXT begin_ = nullptr;
  PFN_vkCmdEndTransformFeedbackEXT end_ = nullptr;
  PFN_vkCmdBeginQueryIndexedEXT beginQuery_ = nullptr;
  PFN_vkCmdEndQueryIndexedEXT endQuery_ = nullptr;
  std::unique_ptr<CapturedCutSplit> split_;
  Buffer buffer_;
  UniqueQueryPool queries_;
  std::uint32_t queryCount_ = 0;
  std::vector<std::uint64_t> capacity_;  // triangles per region
  std::vector<Range> ranges_;            // per region, the last capture's
  std::size_t captures_ = 0;
};

}  // namespace confvis::vulkan
