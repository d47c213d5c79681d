#include "conformal_prepass.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <vector>

#include "confvis/backends/vulkan/byo_descriptors.hpp"
#include "vk_check.hpp"

namespace confvis::vulkan {
namespace {

// BentDispatch of confvis_prepass_common.glsl: VkDispatchIndirectCommand and the list's length.
struct BentDispatch {
  VkDispatchIndirectCommand dispatch;
  std::uint32_t count;
};
static_assert(sizeof(BentDispatch) == 16);

// QueueDispatches of confvis_prepass_common.glsl: vertices, edges, the cut vertices' count,
// edges at the cut.
constexpr int kQueues = 4;

}  // namespace

PrepassThresholds prepassThresholds(const std::vector<glm::vec4>& viewParams,
                                    const std::vector<ErrorWall>& errorWalls, bool splitAlongCut,
                                    bool snapCutToRim) {
  PrepassThresholds thresholds{1e30f, 1e30f, 1e30f, 0.0f, splitAlongCut, snapCutToRim, {}};
  for (const glm::vec4& params : viewParams) {
    if (params.w != 0.0f) {  // tessellation on
      thresholds.maxErrorAngle = std::min(thresholds.maxErrorAngle, params.x);
      thresholds.maxSegmentAngle = params.y;
    }
    thresholds.minGap = std::min(thresholds.minGap, params.z);
    thresholds.maxGap = std::max(thresholds.maxGap, params.z);
  }
  if (thresholds.maxErrorAngle < 1e30f) thresholds.errorWalls = errorWalls;
  return thresholds;
}

ConformalPrepass::ConformalPrepass(VulkanContext& context, const Pipelines& pipelines)
    : context_(context), pipelines_(pipelines) {}

VkDeviceSize ConformalPrepass::commandOffset(std::size_t draw, PrepassList list) {
  return (kPrepassLists * draw + static_cast<std::uint32_t>(list)) *
         sizeof(VkDrawIndexedIndirectCommand);
}

std::uint32_t ConformalPrepass::flatTriangles(std::size_t draw) const {
  // Every triangle of the mesh is flat, on the bent list or outside the source field
  // (UnseenCounts of confvis_prepass_common.glsl counts those).
  const std::uint32_t triangles = (rangeEnds_[draw] - rangeStarts_[draw]) / 3;
  const std::uint32_t bent = static_cast<const BentDispatch*>(bentDispatch_.mapped())[draw].count;
  const std::uint32_t unseen = static_cast<const std::uint32_t*>(unseenCounts_.mapped())[draw];
  return triangles - bent - unseen;
}

std::uint32_t ConformalPrepass::trianglesSplitAlongCut() const {
  return static_cast<const BentDispatch*>(queueDispatch_.mapped())[2].dispatch.x;
}

VkDrawIndexedIndirectCommand ConformalPrepass::command(std::size_t draw, PrepassList list) const {
  VkDrawIndexedIndirectCommand c = static_cast<const VkDrawIndexedIndirectCommand*>(
      commands_.mapped())[commandOffset(draw, list) / sizeof(VkDrawIndexedIndirectCommand)];
  if (list == PrepassList::Dropping) c.firstIndex = rangeEnds_[draw] - c.indexCount;
  return c;
}

void ConformalPrepass::prepare(const GpuScene& scene) {
  if (scene.id() == sceneId_) return;
  const std::size_t indexBytes = scene.triangleCount() * 3 * sizeof(std::uint32_t);
  const VkBufferUsageFlags indexUsage =
      VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  constexpr VkBufferUsageFlags kTexels = VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;
  warped_ = Buffer(context_, scene.extendedVertexCount() * sizeof(glm::vec4),
                   VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | kTexels,
                   false);
  flat_ = Buffer(context_, indexBytes, indexUsage, false);
  pieces_ = Buffer(context_, kPieceCapacity * indexBytes, indexUsage, false);
  tessellated_ = Buffer(context_, indexBytes, indexUsage, false);
  // Shared (host-visible): reset from the host before every frame.
  commands_ = Buffer(context_, commandOffset(scene.draws().size(), PrepassList::Flat),
                     VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                     BufferMemory::Shared);

  // Indirect dispatches (shared: reset before every frame) and the uint lists they run.
  const auto dispatches = [&](std::size_t count) {
    return Buffer(context_, count * sizeof(BentDispatch),
                  VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                  BufferMemory::Shared);
  };
  const auto uintList = [&](std::size_t count) {
    return Buffer(context_, std::max<std::size_t>(count, 1) * sizeof(std::uint32_t),
                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false);
  };
  bentDispatch_ = dispatches(scene.draws().size());
  bentTriangles_ = uintList(scene.triangleCount());
  straightDispatch_ = dispatches(scene.draws().size());
  straightTriangles_ = uintList(scene.triangleCount());
  cutDispatch_ = dispatches(scene.draws().size());
  cutTriangles_ = uintList(scene.triangleCount());
  queueDispatch_ = dispatches(kQueues);
  queuedVertices_ = uintList(scene.vertexCount());
  queuedEdges_ = uintList(2 * scene.edgeCount());  // the bent edges', then the cut's queue
  unseenCounts_ = Buffer(context_, scene.draws().size() * sizeof(std::uint32_t),
                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, BufferMemory::Shared);
  edgeFlags_ = Buffer(context_, std::max<std::size_t>(scene.edgeCount(), 1) * 4,
                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | kTexels, false);  // uint per edge
  edgeCutVertices_ = uintList(2 * scene.edgeCount());
  relative_ = Buffer(context_, std::max<std::size_t>(scene.vertexCount(), 1) * sizeof(glm::vec4),
                     VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | kTexels, false);

  const VkDevice device = context_.device();
  patchLevels_ = Buffer(context_, scene.triangleCount() * 3 * sizeof(glm::vec4),
                        VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false);
  const std::array<VkDescriptorPoolSize, 3> sizes = {{
      {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, kPrepassFirstTexelBinding - 1},
      {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
      {VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, kPrepassBindings - kPrepassFirstTexelBinding},
  }};
  pool_ = UniqueDescriptorPool(device, makeDescriptorPool(device, sizes, 1));
  const VkDescriptorSetLayout layout = pipelines_.prepassSetLayout();
  set_ = allocateDescriptorSets(device, pool_.get(), {&layout, 1}).front();
  // Bindings of confvis_prepass_common.glsl, in order; the scene's vertices, their warps, the
  // edge levels and the cut vertices below; 7 unused (the scene's edges are read through a texel
  // view).
  const std::array<VkBuffer, kPrepassFirstTexelBinding> buffers = {
      VK_NULL_HANDLE,       cutDispatch_.get(),          VK_NULL_HANDLE,
      flat_.get(),          tessellated_.get(),          commands_.get(),
      cutTriangles_.get(),  VK_NULL_HANDLE,              VK_NULL_HANDLE,
      patchLevels_.get(),   pieces_.get(),               bentDispatch_.get(),
      bentTriangles_.get(), queueDispatch_.get(), queuedVertices_.get(),
      queuedEdges_.get(),   unseenCounts_.get(),         edgeFlags_.get(),
      straightDispatch_.get(), straightTriangles_.get(), relative_.get(),
      VK_NULL_HANDLE,       VK_NULL_HANDLE,              edgeCutVertices_.get()};
  for (std::uint32_t i = 0; i < buffers.size(); ++i)
    if (buffers[i] != VK_NULL_HANDLE)
      writeBufferDescriptor(device, set_, i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffers[i]);
  // The parts of the scene's vertex buffer and of the warps (GpuScene's layout: scene vertices,
  // edge midpoints, cut vertices), each bound on its own so that synchronization validation
  // sees the passes touch disjoint ranges.
  const auto bindPart = [&](std::uint32_t binding, VkBuffer buffer, VkDeviceSize elementBytes,
                            std::size_t first, std::size_t end) {
    writeBufferDescriptor(device, set_, binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffer,
                          first * elementBytes, (end - first) * elementBytes);
  };
  const std::size_t midpoints = scene.midpointBase(), cuts = scene.cutVertexBase();
  bindPart(kPrepassVerticesBinding, scene.vertexBuffer(), sizeof(Vertex), 0, midpoints);
  bindPart(kPrepassWarpedBinding, warped_.get(), sizeof(glm::vec4), 0, midpoints);
  bindPart(kPrepassEdgeLevelsBinding, warped_.get(), sizeof(glm::vec4), midpoints, cuts);
  bindPart(kPrepassCutAttributesBinding, scene.vertexBuffer(), sizeof(Vertex), cuts,
           scene.extendedVertexCount());
  bindPart(kPrepassCutWarpsBinding, warped_.get(), sizeof(glm::vec4), cuts,
           scene.extendedVertexCount());
  // The texel views (PrepassTexels), in binding order.
  const std::size_t vertices = scene.vertexCount(), edges = scene.edgeCount();
  const std::size_t indices = 3 * scene.triangleCount();
  texelViews_.clear();
  const auto view = [&](VkBuffer buffer, VkFormat format, VkDeviceSize texelBytes,
                        std::size_t elements, const char* what) {
    const auto binding = kPrepassFirstTexelBinding + static_cast<std::uint32_t>(texelViews_.size());
    texelViews_.push_back(texelView(context_, buffer, format, texelBytes, elements, what));
    writeTexelBufferDescriptor(device, set_, binding, texelViews_.back().get());
  };
  static_assert(sizeof(Vertex) == 2 * sizeof(glm::vec4));
  view(scene.vertexBuffer(), VK_FORMAT_R32G32B32A32_SFLOAT, sizeof(glm::vec4), 2 * vertices,
       "the scene's vertices");
  view(relative_.get(), VK_FORMAT_R32G32B32A32_SFLOAT, sizeof(glm::vec4), vertices,
       "the vertices' virtual points");
  view(warped_.get(), VK_FORMAT_R32G32B32A32_SFLOAT, sizeof(glm::vec4), vertices,
       "the vertices' warps");
  view(scene.edgeBuffer(), VK_FORMAT_R32G32_UINT, sizeof(glm::uvec2), edges, "the scene's edges");
  view(scene.indexBuffer(), VK_FORMAT_R32_UINT, sizeof(std::uint32_t), indices,
       "the scene's indices");
  view(scene.triangleEdgeBuffer(), VK_FORMAT_R32_UINT, sizeof(std::uint32_t), indices,
       "the triangles' edges");
  view(edgeFlags_.get(), VK_FORMAT_R32_UINT, sizeof(std::uint32_t), edges, "the edge flags");
  rangeStarts_.clear();
  rangeEnds_.clear();
  for (const GpuScene::Draw& draw : scene.draws()) {
    rangeStarts_.push_back(draw.firstIndex);
    rangeEnds_.push_back(draw.firstIndex + draw.indexCount);
  }
  sceneId_ = scene.id();
}

void ConformalPrepass::record(VkCommandBuffer cmd, const GpuScene& scene,
                              VkDescriptorSet frameSet, VkDescriptorSet warpSet,
                              const PrepassThresholds& thresholds, GpuStopwatch* passMarks) {
  prepare(scene);
  const auto passDone = [&] {
    if (passMarks) passMarks->mark(cmd);
  };
  // The walls' error bounds: a uniform buffer, whose loads with the loop's uniform index
  // lavapipe makes once for all lanes (as a storage buffer, the bound cost 3 ms of a
  // 20k-triangle pre-pass). More walls than it holds: the strictest bound everywhere.
  if (errorWalls_.get() == VK_NULL_HANDLE)
    errorWalls_ = Buffer(context_, kMaxErrorWalls * sizeof(ErrorWall),
                         VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, BufferMemory::Shared);
  writeBufferDescriptor(context_.device(), set_, kPrepassErrorWallsBinding,
                        VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, errorWalls_.get());
  const std::size_t errorWalls =
      thresholds.errorWalls.size() <= kMaxErrorWalls ? thresholds.errorWalls.size() : 0;
  if (errorWalls > 0)  // data() may be null for an empty list, which memcpy must not get
    std::memcpy(errorWalls_.mapped(), thresholds.errorWalls.data(), errorWalls * sizeof(ErrorWall));

  // Empty lists (the flat list spans the mesh's range: writeFlat), one instance, each mesh's own
  // index range and vertex offset.
  auto* commands = static_cast<VkDrawIndexedIndirectCommand*>(commands_.mapped());
  auto* unseenCounts = static_cast<std::uint32_t*>(unseenCounts_.mapped());
  for (std::size_t d = 0; d < scene.draws().size(); ++d) {
    const GpuScene::Draw& draw = scene.draws()[d];
    for (std::uint32_t list = 0; list < kPrepassLists; ++list)
      commands[kPrepassLists * d + list] = {0, 1, draw.firstIndex, draw.vertexOffset, 0};
    commands[kPrepassLists * d + static_cast<std::uint32_t>(PrepassList::Flat)].indexCount =
        draw.indexCount;
    unseenCounts[d] = 0;
    commands[kPrepassLists * d + static_cast<std::uint32_t>(PrepassList::Pieces)].firstIndex =
        kPieceCapacity * draw.firstIndex;
  }
  auto* bent = static_cast<BentDispatch*>(bentDispatch_.mapped());
  auto* straight = static_cast<BentDispatch*>(straightDispatch_.mapped());
  auto* cut = static_cast<BentDispatch*>(cutDispatch_.mapped());
  for (std::size_t d = 0; d < scene.draws().size(); ++d)
    bent[d] = straight[d] = cut[d] = {0, 1, 1, 0};
  auto* queues = static_cast<BentDispatch*>(queueDispatch_.mapped());
  for (int q = 0; q < kQueues; ++q) queues[q] = {0, 1, 1, 0};

  // The previous frame's draws read what this frame overwrites.
  vkCmdPipelineBarrier(cmd,
                       VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_VERTEX_INPUT_BIT,
                       VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 0, nullptr, 0, nullptr, 0, nullptr);
  const VkPipelineLayout layout = pipelines_.computeLayout();
  const std::array<VkDescriptorSet, 3> sets = {frameSet, warpSet, set_};
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 0, 3, sets.data(), 0,
                          nullptr);
  PrepassConstants push{};
  push.maxErrorAngle = thresholds.maxErrorAngle;
  push.maxSegmentAngle = thresholds.maxSegmentAngle;
  push.minGap = thresholds.minGap;
  push.maxGap = thresholds.maxGap;
  push.splitAlongCut = thresholds.splitAlongCut ? 1u : 0u;
  push.snapCutToRim = thresholds.snapCutToRim ? 1u : 0u;
  push.dropOutside = thresholds.dropOutsideSourceField ? 1u : 0u;
  push.midpointBase = scene.midpointBase();
  push.cutVertexBase = scene.cutVertexBase();
  push.errorWallCount = static_cast<std::uint32_t>(errorWalls);
  constexpr std::uint32_t kGroup = 64;  // local_size_x of the pre-pass shaders
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_.warpVertices());
  push.count = static_cast<std::uint32_t>(scene.vertexCount());
  vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
  vkCmdDispatch(cmd, (push.count + kGroup - 1) / kGroup, 1, 1);
  passDone();

  // A pass's results (and its queue for the next pass, with that pass's dispatch) ready for the
  // next.
  VkMemoryBarrier passResults{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  passResults.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  passResults.dstAccessMask =
      VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_INDIRECT_COMMAND_READ_BIT;
  const auto barrier = [&] {
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT,
                         0, 1, &passResults, 0, nullptr, 0, nullptr);
  };
  barrier();
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_.warpVerticesAcrossCut());
  vkCmdDispatchIndirect(cmd, queueDispatch_.get(), 0);
  passDone();
  barrier();

  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_.classifyEdges());
  push.count = static_cast<std::uint32_t>(scene.edgeCount());
  vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
  vkCmdDispatch(cmd, (push.count + kGroup - 1) / kGroup, 1, 1);
  passDone();
  barrier();
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_.classifyEdgesBent());
  vkCmdDispatchIndirect(cmd, queueDispatch_.get(), sizeof(BentDispatch));
  passDone();
  barrier();
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_.classifyEdgesAtCut());
  vkCmdDispatchIndirect(cmd, queueDispatch_.get(), 3 * sizeof(BentDispatch));
  passDone();
  barrier();

  // Per mesh: its triangles, directly (first pass) or over one of its lists (indirect).
  const auto classifyMeshes = [&](VkPipeline pipeline, const Buffer* list) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
    for (std::size_t d = 0; d < scene.draws().size(); ++d) {
      const GpuScene::Draw& draw = scene.draws()[d];
      push.count = draw.indexCount / 3;
      push.mesh = static_cast<std::uint32_t>(d);
      push.firstIndex = draw.firstIndex;
      push.vertexOffset = draw.vertexOffset;
      vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
      if (list != nullptr)
        vkCmdDispatchIndirect(cmd, list->get(), d * sizeof(BentDispatch));
      else
        vkCmdDispatch(cmd, (push.count + kGroup - 1) / kGroup, 1, 1);
    }
  };
  classifyMeshes(pipelines_.classifyTriangles(), nullptr);
  passDone();
  barrier();
  classifyMeshes(pipelines_.classifyStraightTriangles(), &straightDispatch_);
  passDone();

  // The bent lists and their dispatches are ready; the last pass appends to the same lists.
  VkMemoryBarrier bentReady{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  bentReady.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  bentReady.dstAccessMask =
      VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_INDIRECT_COMMAND_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                       VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT,
                       0, 1, &bentReady, 0, nullptr, 0, nullptr);
  classifyMeshes(pipelines_.classifyBentTriangles(), &bentDispatch_);
  passDone();
  barrier();  // the cut list and its dispatches; the lists both passes append to
  classifyMeshes(pipelines_.splitTrianglesAtCut(), &cutDispatch_);

  VkMemoryBarrier listsReady{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  listsReady.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  listsReady.dstAccessMask = VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_INDEX_READ_BIT |
                             VK_ACCESS_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_HOST_READ_BIT |
                             VK_ACCESS_SHADER_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                       VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_VERTEX_INPUT_BIT |
                           VK_PIPELINE_STAGE_TESSELLATION_CONTROL_SHADER_BIT |
                           VK_PIPELINE_STAGE_HOST_BIT,
                       0, 1, &listsReady, 0, nullptr, 0, nullptr);
}

}  // namespace confvis::vulkan
