#pragma once
// The once-a-frame capture's torn pieces split in compute (issue 23, point 5). The Dropping
// list's geometry shader splits each piece the cut tears into the lone corner's triangle and the
// others' quad, each up to the cut: two bisected crossings, their one-sided limits and two rim
// searches, some 14 map lookups. Lavapipe runs that for all eight lanes of a SIMD group, and with
// a quarter of the pieces torn nearly every group held one: most of the capture's GPU time, on
// the one thread that runs lavapipe's geometry stages. The capture's geometry shader therefore
// only writes each torn piece's corners into the records its split will fill
// (shaders/confvis_captured_split.glsl); find_captured_torn_pieces.comp lists them and
// split_captured_at_cut.comp, over that list alone, writes the split's vertices there, with the
// same code as the geometry shader (shaders/confvis_cut_crossing.glsl). The captured buffer keeps
// the transform feedback's order: the result does not depend on the list's order.
#include <cstdint>
#include <vector>

#include "handles.hpp"
#include "memory.hpp"
#include "pipelines.hpp"

namespace confvis::vulkan {

class CapturedCutSplit {
 public:
  CapturedCutSplit(VulkanContext& context, const Pipelines& pipelines);

  // A region of the captured buffer that the Dropping list's geometry shader wrote.
  struct Region {
    std::uint32_t firstTriangle = 0, capacity = 0;  // triangles
    std::uint32_t query = 0;  // its transform-feedback query (primitives written, needed)
  };

  // Points the passes at `captured` (the capture's buffer, STORAGE_BUFFER usage), which holds at
  // most `triangles` triangles, with room for `queries` queries' results. Call before each
  // capture's recording, with no recorded split pending.
  void bind(VkBuffer captured, std::uint64_t triangles, std::uint32_t queries);

  // Records, after the capture's render pass (its queries ended): the queries' results copied,
  // the torn pieces of `regions` listed and split, and their writes made visible to vertex input.
  void record(VkCommandBuffer cmd, VkQueryPool queries, std::uint32_t queryCount,
              const std::vector<Region>& regions, VkDescriptorSet frameSet, VkDescriptorSet warpSet,
              bool snapToRim);

  // The torn pieces the last completed split found (for tests).
  std::uint32_t tornPieces() const;

 private:
  VulkanContext& context_;
  UniqueDescriptorSetLayout setLayout_;
  UniquePipelineLayout layout_;
  UniquePipeline find_, split_;
  UniqueDescriptorPool pool_;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  Buffer torn_;     // count, indirect dispatch, first triangles
  Buffer written_;  // the queries' results
};

}  // namespace confvis::vulkan
