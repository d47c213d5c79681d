#pragma once
// The pre-pass's flat list split per wall (issue 23, point 5): every wall's pass drew the whole
// flat list through one indirect command per mesh, so lavapipe ran the vertex shader, clipping
// and binning of every flat triangle once per wall (five times in a CAVE). cull_flat_per_wall.comp
// copies into each wall's own list the triangles that may show on it: culled from a wall only
// where, for every eye of the wall, the three warped corners lie outside the same side plane of
// its frustum (conservative: a visible triangle is never dropped). The frusta follow the head,
// which a reused pre-pass does not see, so the cull runs every conformal frame (a cheap pass over
// the flat list). The order within a wall's list follows atomic appends; only triangles that tie
// in depth on the same pixel could tell, as they already can in the pieces list.
// VulkanOptions::cullFlatListPerWall; by default on for GPUs (an H200's 1M-triangle frame:
// 1.52x plain's GPU time without, 0.82x with it) and off for CPU drivers, where the walls' draws
// gained nothing measurable (off-wall triangles seem to be rejected cheaply) while the pass
// itself cost ~6 % of a 200k-triangle frame on lavapipe (backends/vulkan/README.md).
#include <cstdint>
#include <vector>

#include "handles.hpp"
#include "memory.hpp"
#include "pipelines.hpp"

namespace confvis::vulkan {

class GpuScene;

class FlatWallCull {
 public:
  FlatWallCull(VulkanContext& context, const Pipelines& pipelines);

  // Records the cull of `flatIndices` (the pre-pass's flat list, scene-sized, written) for
  // `walls` walls of `eyes` views each (views[w * eyes + e] of the frame set), then a barrier
  // that makes the lists ready for index and indirect reads. wrongFrustaForTests: each wall's
  // list is culled against the next wall's frusta (a broken cull, which the tests must catch).
  void record(VkCommandBuffer cmd, const GpuScene& scene, VkDescriptorSet frameSet,
              VkBuffer flatIndices, VkBuffer warped, std::uint32_t walls, std::uint32_t eyes,
              bool wrongFrustaForTests = false);

  VkBuffer indices() const { return indices_.get(); }
  VkBuffer commands() const { return commands_.get(); }
  // Byte offset in commands() of mesh `draw`'s command in wall `wall`'s list.
  VkDeviceSize commandOffset(std::uint32_t wall, std::size_t draw) const;
  // Triangles in wall `wall`'s list, all meshes; valid once the submission has completed.
  std::uint64_t wallTriangles(std::uint32_t wall) const;
  std::uint32_t walls() const { return walls_; }

 private:
  VulkanContext& context_;
  UniqueDescriptorSetLayout setLayout_;
  UniquePipelineLayout layout_;
  UniquePipeline pipeline_;
  UniqueDescriptorPool pool_;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  Buffer indices_, commands_;
  VkBuffer boundFlat_ = VK_NULL_HANDLE, boundWarped_ = VK_NULL_HANDLE;
  std::uint32_t walls_ = 0;
  std::size_t meshes_ = 0;
};

}  // namespace confvis::vulkan
