#pragma once
// Bring-your-own Vulkan (issue 25): the confvis Vulkan backend's conformal pre-pass as a step an
// application records on its own command buffer, on its own device. The step is the backend's
// own (src/conformal_prepass.cpp): it warps every vertex by the geom map, measures every edge,
// splits the triangles the source's cut crosses exactly along it with their cut vertices snapped
// to the display's rim, and sorts the triangles into the draw lists the warp's pipelines draw
// (backends/vulkan/README.md, "The conformal warp" and "Bring your own Vulkan renderer").
//
// The geometry comes from the application's own vertex and index buffers (PrepassBuffers, read
// once when the step is made) or from host memory (PrepassGeometry), its vertex layout
// described by VertexLayout (float32, float16 and unorm16 attributes).
//
// Per frame: record() on a command buffer, submit it and wait (the tessellated lists' sizes are
// read on the host), then draw each mesh's Flat and Pieces lists with vkCmdDrawIndexedIndirect
// from drawCommandBuffer() and its Tessellated and Dropping lists with vkCmdDraw of drawCommand()
// (below). tools/byo_vulkan_example/app_renderer.cpp is a complete application doing this, run
// by the test suite (backends/vulkan/test/vulkan_byo_test.cpp).
// Thread-safety: one thread at a time per step; record() writes host-visible buffers and
// descriptor sets, so the previous submission of its work and every draw reading its lists must
// have completed before the next record().
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "confvis/base/export.hpp"
#include "confvis/backends/vulkan/byo_device.hpp"
#include "confvis/backends/vulkan/byo_frame.hpp"
#include "confvis/backends/vulkan/byo_upload.hpp"

namespace confvis CONFVIS_API {
namespace vulkan CONFVIS_API {

inline constexpr std::uint32_t kNoAttribute = std::numeric_limits<std::uint32_t>::max();

// Where the attributes lie in one of the application's vertices (byte offsets within `stride`)
// and their formats. Positions (world coordinates) and normals: VK_FORMAT_R32G32B32_SFLOAT,
// R32G32B32A32_SFLOAT or R16G16B16A16_SFLOAT (xyz read, w ignored); uvs: R32G32_SFLOAT,
// R16G16_SFLOAT or R16G16_UNORM. kNoAttribute: none (the draws then get zero normals or uvs).
// Any other format is refused with Error(InvalidInput) naming it. The step converts them to
// float32 (ConformalVertex, below): the draw lists' vertices are always float32.
struct VertexLayout {
  std::uint32_t stride = 0;
  std::uint32_t positionOffset = 0;
  VkFormat positionFormat = VK_FORMAT_R32G32B32_SFLOAT;
  std::uint32_t normalOffset = kNoAttribute;
  VkFormat normalFormat = VK_FORMAT_R32G32B32_SFLOAT;
  std::uint32_t uvOffset = kNoAttribute;
  VkFormat uvFormat = VK_FORMAT_R32G32_SFLOAT;
};

// A mesh: a range of the index list, its indices relative to vertexOffset (as in
// vkCmdDrawIndexed). Each mesh gets its own draw commands, so that the application can bind its
// material between them.
struct PrepassMesh {
  std::uint32_t firstIndex = 0, indexCount = 0;
  std::int32_t vertexOffset = 0;
};

// The application's geometry as it uploads it to its own vertex buffer: `vertexCount` vertices
// of `layout.stride` bytes from `vertices` and the triangle list's indices. Read once, by the
// constructor.
struct PrepassGeometry {
  const void* vertices = nullptr;
  std::size_t vertexCount = 0;
  VertexLayout layout;
  std::vector<std::uint32_t> indices;
  std::vector<PrepassMesh> meshes;  // empty: one mesh over every index, vertexOffset 0
};

// The application's geometry in its own device buffers, as its pipeline draws it with
// vkCmdBindVertexBuffers(vertexBuffer, vertexOffset) and vkCmdBindIndexBuffer(indexBuffer,
// indexOffset, indexType): `vertexCount` vertices of `layout.stride` bytes and `indexCount`
// indices of a triangle list. Both buffers need VK_BUFFER_USAGE_TRANSFER_SRC_BIT and must hold
// their data (the application's upload completed) when the step is constructed.
struct PrepassBuffers {
  VkBuffer vertexBuffer = VK_NULL_HANDLE;
  VkDeviceSize vertexOffset = 0;
  std::size_t vertexCount = 0;
  VertexLayout layout;
  VkBuffer indexBuffer = VK_NULL_HANDLE;
  VkDeviceSize indexOffset = 0;
  std::uint32_t indexCount = 0;
  VkIndexType indexType = VK_INDEX_TYPE_UINT32;  // or VK_INDEX_TYPE_UINT16
  std::vector<PrepassMesh> meshes;  // empty: one mesh over every index, vertexOffset 0
};

// The vertex of the step's vertex buffer (vertexBuffer()): the application's vertices converted,
// then the edge midpoints and the pre-pass's cut vertices. A pipeline drawing the flat and pieces
// lists reads it at binding 0 (stride 32: position location 0, normal 1, uv 2) and the warps at
// binding 1 (warpBuffer(), stride 16, location 3: RGBA32F, xyz relative to the warp centre).
struct ConformalVertex {
  float position[3];
  float normal[3];
  float uv[2];
};
static_assert(sizeof(ConformalVertex) == 32);

// One wall the frame draws, at `width` x `height` pixels: the pre-pass keeps each bent edge
// within the error bound of the pixels it is shown on.
struct PrepassWall {
  const Wall* wall = nullptr;
  std::uint32_t width = 0, height = 0;
};

struct PrepassFrame {
  glm::dmat4 worldToPhysical{1.0};  // the navigation (worldToPhysical(config, camera))
  std::vector<PrepassWall> walls;   // at least one
  WarpTolerances tolerances;
  bool tessellate = true;           // false: everything flat (a deliberately coarse warp)
  bool splitAlongCut = true;        // VulkanOptions::splitAlongCut
  bool snapCutToRim = true;         // VulkanOptions::snapCutToRim
};

// The lists, in the order of a mesh's draw commands.
enum class DrawList : std::uint32_t {
  Flat = 0,         // indexed (flatIndices()), drawn flat: warp_simple.vert
  Tessellated = 1,  // warp.vert + warp.tesc + warp_projected.tese
  Dropping = 2,     // warp.vert + warp.tesc + warp.tese + warp.geom (drops pieces across the cut)
  Pieces = 3,       // indexed (pieceIndices()), drawn flat like Flat
};

// Thread-safety: one thread at a time per step (see the top of this header).
class ConformalPrepassStep {
 public:
  // Converts and uploads the geometry (with its edge list and midpoints) and creates the
  // pre-pass's pipelines on the application's device. Throws Error(InvalidInput) naming what is
  // wrong with the geometry (null data, a stride smaller than an attribute, an unsupported
  // format, an index outside its mesh's vertices, a mesh outside the index list).
  ConformalPrepassStep(const AppDevice& app, const PrepassGeometry& geometry);
  // From the application's own buffers. Their contents are copied back once, by a transfer
  // this constructor records and submits on app.queue and waits for (a VkBuffer is read on the
  // host only through such a copy): the pre-pass's per-frame work runs on the device, but it
  // needs the mesh's distinct edges, its edge midpoints and the slots for cut vertices laid out
  // beside the vertices, and those are built on the host from the topology, once per geometry.
  // Geometry that changes (new vertices or indices) takes a new step. The same errors as above,
  // and Error(InvalidInput) for a null buffer, an index type other than UINT16 / UINT32, or a
  // range larger than its buffer's memory requirements (Vulkan does not tell a buffer's size:
  // a range past its end but within that is the application's error, which the validation
  // layer reports).
  ConformalPrepassStep(const AppDevice& app, const PrepassBuffers& buffers);
  ~ConformalPrepassStep();
  ConformalPrepassStep(const ConformalPrepassStep&) = delete;
  ConformalPrepassStep& operator=(const ConformalPrepassStep&) = delete;

  // Records the pre-pass on `cmd` (a primary command buffer in the recording state, outside a
  // render pass, on app.queue's family): resets its lists from the host, binds its own compute
  // pipelines and descriptor sets, dispatches, and ends with a barrier that makes the lists
  // ready for index, vertex-attribute, indirect-command and tessellation-control reads. `map`
  // must stay alive until the submission completes.
  void record(VkCommandBuffer cmd, const UploadedRetargetMap& map, const PrepassFrame& frame);

  std::size_t meshCount() const;
  // Buffers the application's pipelines read:
  VkBuffer vertexBuffer() const;  // ConformalVertex, extended (binding 0 of the flat pipeline)
  VkBuffer warpBuffer() const;    // vec4 per extended vertex (binding 1); storage for warp.vert
  VkBuffer flatIndices() const;   // index buffer (uint32) of the Flat list
  VkBuffer pieceIndices() const;  // index buffer (uint32) of the Pieces list
  // Storage buffers of warp.vert / warp.tesc (confvis_pulled_vertex.glsl,
  // confvis_render_common.glsl): the tessellated lists' indices (set 0, binding 3) and their
  // edge levels (binding 2); vertexBuffer() and warpBuffer() are bindings 4 and 5.
  VkBuffer tessellatedIndices() const;
  VkBuffer patchLevels() const;
  // VkDrawIndexedIndirectCommand per mesh and list (drawCommandOffset), for
  // vkCmdDrawIndexedIndirect of the Flat and Pieces lists.
  VkBuffer drawCommandBuffer() const;
  static VkDeviceSize drawCommandOffset(std::size_t mesh, DrawList list);
  // A list's command as the pre-pass left it (host read: valid once the recorded work has
  // completed). The Tessellated and Dropping lists are drawn without an index buffer:
  // vkCmdDraw(c.indexCount, 1, c.firstIndex, 0) with push constant vertexOffset = c.vertexOffset
  // (warp.vert reads the list itself).
  VkDrawIndexedIndirectCommand drawCommand(std::size_t mesh, DrawList list) const;
  // Whether the layout had normals (the shaders' push constant hasNormals).
  bool hasNormals() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vulkan
}  // namespace confvis
