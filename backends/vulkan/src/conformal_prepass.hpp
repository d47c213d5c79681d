#pragma once
// The conformal pre-pass, once per frame for all walls and eyes: warps every scene vertex
// (warp_vertices.comp) and sorts every triangle into "flat" (drawn between its warped corners by
// a plain vertex shader) or "tessellated" (drawn through the tessellation pipeline, which bends,
// culls and drops it), writing one compacted index list and one indirect draw command per mesh
// and kind (classify_triangles.comp), with each distinct edge's level measured once before
// (classify_edges.comp) and copied next to the tessellated list for warp.tesc. Per-patch
// tessellation is costly on some devices (lavapipe
// above all); most triangles of a finely meshed scene need none.
#include <cstdint>

#include "gpu_scene.hpp"
#include "memory.hpp"
#include "pipelines.hpp"

namespace confvis::vulkan {

struct PrepassThresholds {
  float maxErrorAngle;    // radians: the smallest over the frame's walls
  float maxSegmentAngle;  // radians
  float minGap;           // radians
};

class ConformalPrepass {
 public:
  ConformalPrepass(VulkanContext& context, const Pipelines& pipelines);

  // Records both passes for `scene` (buffers are rebuilt when the scene changed) and a barrier
  // that makes their results ready for vertex input, index and indirect-command reads.
  void record(VkCommandBuffer cmd, const GpuScene& scene, VkDescriptorSet frameSet,
              VkDescriptorSet warpSet, const PrepassThresholds& thresholds);

  VkBuffer warped() const { return warped_.get(); }  // vec4 per vertex: warp relative to c, validity
  VkBuffer flatIndices() const { return flat_.get(); }
  VkBuffer tessellatedIndices() const { return tessellated_.get(); }
  VkBuffer commands() const { return commands_.get(); }
  // vec4 per tessellated-list index: level of the edge opposite that corner (warp.tesc).
  VkBuffer patchLevels() const { return patchLevels_.get(); }
  std::uint64_t sceneId() const { return sceneId_; }  // of the scene the buffers are for
  // The command as the pre-pass left it; valid once its submission has completed.
  VkDrawIndexedIndirectCommand command(std::size_t draw, bool tessellated) const {
    return static_cast<const VkDrawIndexedIndirectCommand*>(commands_.mapped())
        [2 * draw + (tessellated ? 1 : 0)];
  }
  // Byte offset of mesh `draw`'s VkDrawIndexedIndirectCommand of the given kind.
  static VkDeviceSize commandOffset(std::size_t draw, bool tessellated);

 private:
  void prepare(const GpuScene& scene);

  VulkanContext& context_;
  const Pipelines& pipelines_;
  std::uint64_t sceneId_ = 0;
  Buffer warped_, flat_, tessellated_, commands_, edgeLevels_, patchLevels_;
  UniqueDescriptorPool pool_;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
};

}  // namespace confvis::vulkan
