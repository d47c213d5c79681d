#pragma once
// The conformal pre-pass, once per frame for all walls and eyes: warps every scene vertex
// (warp_vertices.comp; the few next to the source's cut, which need the four-texel lookup, in an
// indirect pass of their own), measures every distinct edge once (classify_edges.comp: cheap
// tests finish the straight ones; classify_edges_bent.comp, indirect, measures the rest) and
// sorts every triangle into "flat" (drawn between its warped corners by a plain vertex shader),
// "pieces" (split at its edge midpoints, drawn flat), "tessellated" (the tessellation pipeline,
// which bends and culls it) or "dropping" (tessellation and a geometry shader that drops pieces
// across the cut or outside the source field): classify_triangles.comp runs the flat test over
// every triangle from its edges' flags and writes the flat list in the scene's order (degenerate
// triangles where not flat); classify_straight_triangles.comp, dispatched indirectly, runs the
// full drop test on the straight triangles too large for the flags' test;
// classify_bent_triangles.comp, indirectly too, sorts the rest into compacted lists with one
// draw command per mesh and list, but for those the cut crosses, which
// split_triangles_at_cut.comp splits along it. Per-patch tessellation is costly
// on some devices (lavapipe above all: its vertex, tessellation and geometry stages run on one
// thread); most triangles of a finely meshed scene need none, and few of the rest need the
// geometry shader. Lavapipe also runs both sides of every branch for all SIMD lanes, hence the
// cheap first passes and the short indirect ones.
#include <array>
#include <cstdint>
#include <vector>

#include "gpu_scene.hpp"
#include "gpu_stopwatch.hpp"
#include "memory.hpp"
#include "pipelines.hpp"

namespace confvis::vulkan {

// Pieces-list index slots per index of the scene: a triangle split at its edge midpoints makes
// up to four (classify_bent_triangles.comp, kPieceCapacity).
constexpr std::uint32_t kPieceCapacity = 4;

enum class PrepassList : std::uint32_t { Flat = 0, Tessellated = 1, Dropping = 2, Pieces = 3 };
constexpr std::uint32_t kPrepassLists = 4;  // commands per mesh, kList* of the shaders

struct PrepassThresholds {
  float maxErrorAngle;    // radians: the smallest over the frame's walls
  float maxSegmentAngle;  // radians
  float minGap;           // radians: the smallest over the frame's views
  float maxGap;           // radians: the largest (the pre-pass decides a drop only where both agree)
  bool splitAlongCut = true;  // VulkanOptions::splitAlongCut
  bool snapCutToRim = true;   // VulkanOptions::snapCutToRim
  // The walls' local bend error bounds (FramePlan::errorWalls): segments of bent edges keep to
  // errorPixels of the pixels where they are shown; maxErrorAngle is the smallest anywhere.
  std::vector<ErrorWall> errorWalls;
  bool dropOutsideSourceField = false;  // VulkanOptions::dropOutsideSourceField
  bool operator==(const PrepassThresholds&) const = default;
};

// The thresholds for a frame whose views have these View::params (x: bend error, y: segment
// angle, z: cut gap, radians; w: 1 to tessellate): the strictest wall's, so that no wall needs
// more than the flat list gives. The frame renderer and the bring-your-own step share it.
PrepassThresholds prepassThresholds(const std::vector<glm::vec4>& viewParams,
                                    const std::vector<ErrorWall>& errorWalls, bool splitAlongCut,
                                    bool snapCutToRim);

class ConformalPrepass {
 public:
  ConformalPrepass(VulkanContext& context, const Pipelines& pipelines);

  // Records the passes for `scene` (buffers are rebuilt when the scene changed) and a barrier
  // that makes their results ready for vertex input, index and indirect-command reads.
  // `passMarks` (started): a mark after each pass but the last, so that its intervals up to its
  // stop are the passes' GPU times, in kPassNames' order.
  void record(VkCommandBuffer cmd, const GpuScene& scene, VkDescriptorSet frameSet,
              VkDescriptorSet warpSet, const PrepassThresholds& thresholds,
              GpuStopwatch* passMarks = nullptr);
  static constexpr std::array<const char*, 9> kPassNames = {
      "warp_vertices",          "warp_vertices_across_cut",    "classify_edges",
      "classify_edges_bent",    "classify_edges_at_cut",       "classify_triangles",
      "classify_straight_triangles", "classify_bent_triangles", "split_triangles_at_cut"};

  // vec4 per vertex of the scene's vertex buffer (GpuScene's layout: scene vertices, edge
  // midpoints, cut vertices): warp relative to c, w = validity (midpoints: their segments).
  VkBuffer warped() const { return warped_.get(); }
  VkBuffer flatIndices() const { return flat_.get(); }
  VkBuffer pieceIndices() const { return pieces_.get(); }  // kPieceCapacity slots per scene index
  VkBuffer tessellatedIndices() const { return tessellated_.get(); }  // both tessellated lists
  VkBuffer commands() const { return commands_.get(); }
  // vec4 per tessellated-lists index: level of the edge opposite that corner (warp.tesc).
  VkBuffer patchLevels() const { return patchLevels_.get(); }
  std::uint64_t sceneId() const { return sceneId_; }  // of the scene the buffers are for
  // Mesh `draw`'s command for `list` as the pre-pass left it, with the list's true first index
  // (the dropping list ends where the mesh's range does); valid once its submission has
  // completed.
  VkDrawIndexedIndirectCommand command(std::size_t draw, PrepassList list) const;
  // Mesh `draw`'s triangles in the flat list that are not degenerate (the list holds the whole
  // mesh's range); valid once the submission has completed.
  std::uint32_t flatTriangles(std::size_t draw) const;
  // Triangles split along the source's cut (split_triangles_at_cut.comp), all meshes; valid
  // once the submission has completed.
  std::uint32_t trianglesSplitAlongCut() const;
  // Byte offset of mesh `draw`'s VkDrawIndexedIndirectCommand for `list`.
  static VkDeviceSize commandOffset(std::size_t draw, PrepassList list);

 private:
  void prepare(const GpuScene& scene);

  VulkanContext& context_;
  const Pipelines& pipelines_;
  std::uint64_t sceneId_ = 0;
  std::vector<std::uint32_t> rangeStarts_;  // per mesh: its first index
  std::vector<std::uint32_t> rangeEnds_;    // per mesh: one past its last index
  Buffer warped_, flat_, pieces_, tessellated_, commands_, patchLevels_;
  // Per mesh: VkDispatchIndirectCommand and bent-list length (BentDispatch of the shaders).
  Buffer bentDispatch_;
  Buffer bentTriangles_;  // uint per scene triangle
  // The same for the straight list (classify_straight_triangles.comp).
  Buffer straightDispatch_, straightTriangles_;
  // The same for the cut list (split_triangles_at_cut.comp).
  Buffer cutDispatch_, cutTriangles_;
  // The vertices queued for lookups across the cut, the edges for full measurement: two
  // BentDispatch, the lists (uint each).
  Buffer queueDispatch_, queuedVertices_, queuedEdges_;
  Buffer unseenCounts_;  // uint per mesh, shared: its triangles outside the source field
  Buffer edgeFlags_;   // uint per scene edge
  Buffer edgeCutVertices_;  // uvec2 per scene edge: its cut vertices' first slot, the crossing
  Buffer relative_;    // vec4 per scene vertex: its point relative to c
  Buffer errorWalls_;  // uniform: ErrorWall[kMaxErrorWalls], shared
  UniqueDescriptorPool pool_;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  std::vector<UniqueBufferView> texelViews_;  // PrepassTexels, after the set that uses them
};

}  // namespace confvis::vulkan
