// Bring-your-own Vulkan: the backend's conformal pre-pass (conformal_prepass.cpp) on the
// application's device and command buffer (byo_prepass.hpp).
#include "confvis/backends/vulkan/byo_prepass.hpp"

#include <array>
#include <cmath>
#include <cstring>
#include <string>

#include "byo_internal.hpp"
#include "byo_vertex_formats.hpp"
#include "confvis/backends/vulkan/byo_descriptors.hpp"
#include "confvis/backends/vulkan/warp_interface.hpp"
#include "confvis/base/error.hpp"
#include "conformal_prepass.hpp"
#include "error_walls.hpp"
#include "gpu_scene.hpp"
#include "pipelines.hpp"
#include "vk_check.hpp"

namespace confvis::vulkan {
namespace {

[[noreturn]] void badGeometry(const std::string& what) {
  throw Error(ErrorCode::InvalidInput, "pre-pass geometry: " + what);
}

// Checks one attribute of the layout; returns whether the layout has it.
bool checkAttribute(const VertexLayout& layout, AttributeRole role, const char* name,
                    std::uint32_t offset, VkFormat format) {
  if (offset == kNoAttribute) return false;
  const std::uint32_t bytes = attributeBytes(role, name, format);
  if (std::size_t{offset} + bytes > layout.stride)
    badGeometry(std::string(name) + " at offset " + std::to_string(offset) + " (" +
                std::to_string(bytes) + " bytes, " + vertexFormatName(format) +
                ") does not fit the stride " + std::to_string(layout.stride));
  return true;
}

// The application's vertices in the backend's layout (GpuScene's Vertex), converted to float.
std::vector<Vertex> convertVertices(const PrepassGeometry& geometry) {
  const VertexLayout& layout = geometry.layout;
  if (geometry.vertices == nullptr || geometry.vertexCount == 0) badGeometry("no vertices");
  if (layout.positionOffset == kNoAttribute) badGeometry("the layout has no position");
  checkAttribute(layout, AttributeRole::Position, "position", layout.positionOffset,
                 layout.positionFormat);
  const bool normals = checkAttribute(layout, AttributeRole::Normal, "normal",
                                      layout.normalOffset, layout.normalFormat);
  const bool uvs =
      checkAttribute(layout, AttributeRole::Uv, "uv", layout.uvOffset, layout.uvFormat);
  const auto* bytes = static_cast<const unsigned char*>(geometry.vertices);
  std::vector<Vertex> vertices(geometry.vertexCount, Vertex{});
  for (std::size_t i = 0; i < geometry.vertexCount; ++i) {
    const unsigned char* v = bytes + i * layout.stride;
    Vertex& out = vertices[i];
    out.position = readAttribute(layout.positionFormat, v + layout.positionOffset);
    if (normals) out.normal = readAttribute(layout.normalFormat, v + layout.normalOffset);
    if (uvs) out.uv = glm::vec2(readAttribute(layout.uvFormat, v + layout.uvOffset));
    if (!std::isfinite(out.position.x) || !std::isfinite(out.position.y) ||
        !std::isfinite(out.position.z))
      badGeometry("vertex " + std::to_string(i) + " has a non-finite position");
  }
  return vertices;
}

std::vector<GpuScene::Draw> meshDraws(const PrepassGeometry& geometry) {
  const std::size_t indices = geometry.indices.size();
  if (indices == 0 || indices % 3 != 0)
    badGeometry(std::to_string(indices) + " indices is not a triangle list");
  std::vector<PrepassMesh> meshes = geometry.meshes;
  if (meshes.empty()) meshes.push_back({0, static_cast<std::uint32_t>(indices), 0});
  std::vector<GpuScene::Draw> draws;
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const PrepassMesh& mesh = meshes[m];
    const std::string name = "mesh " + std::to_string(m);
    if (mesh.indexCount % 3 != 0 || std::size_t{mesh.firstIndex} + mesh.indexCount > indices)
      badGeometry(name + ": indices " + std::to_string(mesh.firstIndex) + " + " +
                  std::to_string(mesh.indexCount) + " are not triangles within the " +
                  std::to_string(indices) + " indices");
    for (std::uint32_t i = mesh.firstIndex; i < mesh.firstIndex + mesh.indexCount; ++i) {
      const std::int64_t vertex = std::int64_t{geometry.indices[i]} + mesh.vertexOffset;
      if (vertex < 0 || vertex >= static_cast<std::int64_t>(geometry.vertexCount))
        badGeometry(name + ": index " + std::to_string(i) + " names vertex " +
                    std::to_string(vertex) + " of " + std::to_string(geometry.vertexCount));
    }
    GpuScene::Draw draw;
    draw.firstIndex = mesh.firstIndex;
    draw.indexCount = mesh.indexCount;
    draw.vertexOffset = mesh.vertexOffset;
    draw.hasNormals = geometry.layout.normalOffset != kNoAttribute;
    draws.push_back(draw);
  }
  return draws;
}

// The application's buffers read back (the host builds the edge list from the indices; see the
// constructor's comment in byo_prepass.hpp): bytes of the vertices and the indices as uint32.
struct ReadBack {
  std::vector<unsigned char> vertices;
  PrepassGeometry geometry;
};

void checkRange(VkDevice device, VkBuffer buffer, VkDeviceSize offset, VkDeviceSize bytes,
                const char* what) {
  if (buffer == VK_NULL_HANDLE) badGeometry(std::string("no ") + what + " buffer");
  VkMemoryRequirements needs;
  vkGetBufferMemoryRequirements(device, buffer, &needs);
  if (offset + bytes > needs.size)
    badGeometry(std::string(what) + " range " + std::to_string(offset) + " + " +
                std::to_string(bytes) + " bytes lies past the buffer's " +
                std::to_string(needs.size) + " bytes of memory");
}

ReadBack readBack(const AppDevice& app, const PrepassBuffers& buffers) {
  const VertexLayout& layout = buffers.layout;
  if (buffers.vertexCount == 0) badGeometry("no vertices");
  if (layout.stride == 0) badGeometry("the layout's stride is 0");
  if (buffers.indexType != VK_INDEX_TYPE_UINT32 && buffers.indexType != VK_INDEX_TYPE_UINT16)
    badGeometry("index type " + std::to_string(buffers.indexType) +
                " is not supported (VK_INDEX_TYPE_UINT16 or VK_INDEX_TYPE_UINT32)");
  if (buffers.indexCount == 0 || buffers.indexCount % 3 != 0)
    badGeometry(std::to_string(buffers.indexCount) + " indices is not a triangle list");
  const VkDeviceSize vertexBytes = VkDeviceSize{buffers.vertexCount} * layout.stride;
  const VkDeviceSize indexSize = buffers.indexType == VK_INDEX_TYPE_UINT16 ? 2 : 4;
  const VkDeviceSize indexBytes = VkDeviceSize{buffers.indexCount} * indexSize;
  checkRange(app.device, buffers.vertexBuffer, buffers.vertexOffset, vertexBytes, "vertex");
  checkRange(app.device, buffers.indexBuffer, buffers.indexOffset, indexBytes, "index");

  VulkanContext context(app);
  const VkDeviceSize indexStart = (vertexBytes + 3) / 4 * 4;
  Buffer staging(context, indexStart + indexBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                 BufferMemory::Host);
  context.submitAndWait([&](VkCommandBuffer cmd) {
    const VkBufferCopy vertexCopy{buffers.vertexOffset, 0, vertexBytes};
    vkCmdCopyBuffer(cmd, buffers.vertexBuffer, staging.get(), 1, &vertexCopy);
    const VkBufferCopy indexCopy{buffers.indexOffset, indexStart, indexBytes};
    vkCmdCopyBuffer(cmd, buffers.indexBuffer, staging.get(), 1, &indexCopy);
    VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                         &toHost, 0, nullptr, 0, nullptr);
  });
  ReadBack result;
  const auto* mapped = static_cast<const unsigned char*>(staging.mapped());
  result.vertices.assign(mapped, mapped + vertexBytes);
  PrepassGeometry& geometry = result.geometry;
  geometry.vertices = result.vertices.data();
  geometry.vertexCount = buffers.vertexCount;
  geometry.layout = layout;
  geometry.meshes = buffers.meshes;
  geometry.indices.resize(buffers.indexCount);
  const unsigned char* indices = mapped + indexStart;
  for (std::uint32_t i = 0; i < buffers.indexCount; ++i) {
    if (indexSize == 2) {
      std::uint16_t index;
      std::memcpy(&index, indices + 2 * std::size_t{i}, 2);
      geometry.indices[i] = index;
    } else {
      std::memcpy(&geometry.indices[i], indices + 4 * std::size_t{i}, 4);
    }
  }
  return result;
}

}  // namespace

struct ConformalPrepassStep::Impl {
  // `vertices` and `draws`: the geometry, validated before any Vulkan object is made.
  Impl(const AppDevice& app, std::vector<Vertex> vertices, const PrepassGeometry& geometry,
       std::vector<GpuScene::Draw> draws)
      : context(std::make_unique<VulkanContext>(app)),
        pipelines(*context),
        scene(*context, std::move(vertices), geometry.indices, std::move(draws),
              "pre-pass geometry"),
        prepass(*context, pipelines),
        hasNormals(geometry.layout.normalOffset != kNoAttribute) {
    FrameDescriptors made = allocateFrameDescriptors(*context, pipelines);
    pool = std::move(made.pool);
    frameSet = made.frameSet;
    warpSet = made.warpSet;
    frameUniforms = std::move(made.frameUniforms);
  }

  std::unique_ptr<VulkanContext> context;  // on the application's device; destroyed last
  Pipelines pipelines;
  GpuScene scene;
  ConformalPrepass prepass;
  bool hasNormals;
  Buffer frameUniforms;
  UniqueDescriptorPool pool;
  VkDescriptorSet frameSet = VK_NULL_HANDLE, warpSet = VK_NULL_HANDLE;
};

ConformalPrepassStep::ConformalPrepassStep(const AppDevice& app, const PrepassGeometry& geometry)
    : impl_(std::make_unique<Impl>(app, convertVertices(geometry), geometry,
                                   meshDraws(geometry))) {}

ConformalPrepassStep::ConformalPrepassStep(const AppDevice& app, const PrepassBuffers& buffers)
    : ConformalPrepassStep(app, readBack(app, buffers).geometry) {}

ConformalPrepassStep::~ConformalPrepassStep() = default;

void ConformalPrepassStep::record(VkCommandBuffer cmd, const UploadedRetargetMap& map,
                                  const PrepassFrame& frame) {
  if (frame.walls.empty())
    throw Error(ErrorCode::InvalidInput, "pre-pass frame: no wall to draw");
  const glm::dvec3 c = map.reference();
  std::vector<glm::vec4> viewParams;
  std::vector<ErrorWall> errorWalls;
  for (const PrepassWall& target : frame.walls) {
    if (target.wall == nullptr) throw Error(ErrorCode::InvalidInput, "pre-pass frame: null wall");
    const WallWarpBounds bounds =
        wallWarpBounds(*target.wall, target.width, target.height, c, frame.tolerances);
    viewParams.emplace_back(bounds.errorAngle, bounds.maxSegmentAngle, bounds.cutGapAngle,
                            frame.tessellate ? 1.0f : 0.0f);
    errorWalls.push_back(
        errorWall(*target.wall, target.width, target.height, c, frame.tolerances.errorPixels));
  }
  const PrepassThresholds thresholds =
      prepassThresholds(viewParams, errorWalls, frame.splitAlongCut, frame.snapCutToRim);
  const FrameUniforms uniforms{glm::mat4(frame.worldToPhysical), glm::vec4(glm::vec3(c), 1.0f)};
  std::memcpy(impl_->frameUniforms.mapped(), &uniforms, sizeof(uniforms));
  const VkDevice device = impl_->context->device();
  writeWarpSet(device, impl_->warpSet, map);
  impl_->prepass.record(cmd, impl_->scene, impl_->frameSet, impl_->warpSet, thresholds);
}

std::size_t ConformalPrepassStep::meshCount() const { return impl_->scene.draws().size(); }
VkBuffer ConformalPrepassStep::vertexBuffer() const { return impl_->scene.vertexBuffer(); }
VkBuffer ConformalPrepassStep::warpBuffer() const { return impl_->prepass.warped(); }
VkBuffer ConformalPrepassStep::flatIndices() const { return impl_->prepass.flatIndices(); }
VkBuffer ConformalPrepassStep::pieceIndices() const { return impl_->prepass.pieceIndices(); }
VkBuffer ConformalPrepassStep::tessellatedIndices() const {
  return impl_->prepass.tessellatedIndices();
}
VkBuffer ConformalPrepassStep::patchLevels() const { return impl_->prepass.patchLevels(); }
VkBuffer ConformalPrepassStep::drawCommandBuffer() const { return impl_->prepass.commands(); }
bool ConformalPrepassStep::hasNormals() const { return impl_->hasNormals; }

VkDeviceSize ConformalPrepassStep::drawCommandOffset(std::size_t mesh, DrawList list) {
  return ConformalPrepass::commandOffset(mesh, static_cast<PrepassList>(list));
}

VkDrawIndexedIndirectCommand ConformalPrepassStep::drawCommand(std::size_t mesh,
                                                               DrawList list) const {
  if (mesh >= meshCount())
    throw Error(ErrorCode::InvalidInput, "pre-pass: mesh " + std::to_string(mesh) + " of " +
                                             std::to_string(meshCount()));
  return impl_->prepass.command(mesh, static_cast<PrepassList>(list));
}

static_assert(sizeof(ConformalVertex) == sizeof(Vertex));
static_assert(static_cast<std::uint32_t>(DrawList::Pieces) ==
              static_cast<std::uint32_t>(PrepassList::Pieces));
static_assert(static_cast<std::uint32_t>(DrawList::Dropping) ==
              static_cast<std::uint32_t>(PrepassList::Dropping));

}  // namespace confvis::vulkan
