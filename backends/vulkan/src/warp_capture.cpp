#include "warp_capture.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <string>

#include "confvis/base/error.hpp"
#include "vk_check.hpp"

namespace confvis::vulkan {
namespace {

constexpr std::array<PrepassList, 2> kCapturedLists = {PrepassList::Tessellated,
                                                       PrepassList::Dropping};
// A region's first size: triangles per patch (a patch of level n gives about n^2 triangles, the
// geometry shader up to three for each of its own). Too few costs one more capture, once.
constexpr std::uint64_t kFirstTrianglesPerPatch = 16;

template <typename Function>
Function deviceFunction(VkDevice device, const char* name) {
  const auto function = reinterpret_cast<Function>(vkGetDeviceProcAddr(device, name));
  if (!function)
    throw Error(ErrorCode::DeviceUnsupported,
                std::string("the Vulkan device has no ") + name + " (VK_EXT_transform_feedback)");
  return function;
}

}  // namespace

WarpCapture::WarpCapture(VulkanContext& context, Pipelines& pipelines)
    : context_(context), pipelines_(pipelines) {
  const VkDevice device = context.device();
  bindBuffers_ = deviceFunction<PFN_vkCmdBindTransformFeedbackBuffersEXT>(
      device, "vkCmdBindTransformFeedbackBuffersEXT");
  begin_ = deviceFunction<PFN_vkCmdBeginTransformFeedbackEXT>(device,
                                                              "vkCmdBeginTransformFeedbackEXT");
  end_ = deviceFunction<PFN_vkCmdEndTransformFeedbackEXT>(device, "vkCmdEndTransformFeedbackEXT");
  beginQuery_ = deviceFunction<PFN_vkCmdBeginQueryIndexedEXT>(device, "vkCmdBeginQueryIndexedEXT");
  endQuery_ = deviceFunction<PFN_vkCmdEndQueryIndexedEXT>(device, "vkCmdEndQueryIndexedEXT");
  split_ = std::make_unique<CapturedCutSplit>(context, pipelines);
}

std::size_t WarpCapture::region(std::size_t draw, PrepassList list) {
  return 2 * draw + (list == PrepassList::Tessellated ? 0 : 1);
}

WarpCapture::Range WarpCapture::range(std::size_t draw, PrepassList list) const {
  const std::size_t r = region(draw, list);
  return r < ranges_.size() ? ranges_[r] : Range{};
}

std::optional<double> WarpCapture::capture(const GpuScene& scene, const ConformalPrepass& prepass,
                                           VkDescriptorSet frameSet, VkDescriptorSet warpSet,
                                           std::uint32_t captureView, bool snapToRim,
                                           bool splitTornPieces, GpuStopwatch& stopwatch) {
  const std::size_t regions = 2 * scene.draws().size();
  capacity_.resize(regions, 0);
  ranges_.assign(regions, Range{});
  if (queryCount_ < regions) {
    VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    info.queryType = VK_QUERY_TYPE_TRANSFORM_FEEDBACK_STREAM_EXT;
    info.queryCount = static_cast<std::uint32_t>(regions);
    VkQueryPool pool = VK_NULL_HANDLE;
    check(vkCreateQueryPool(context_.device(), &info, nullptr, &pool), "vkCreateQueryPool");
    queries_ = UniqueQueryPool(context_.device(), pool);
    queryCount_ = info.queryCount;
  }
  std::optional<double> gpuSeconds;
  for (int attempt = 0; attempt < 2; ++attempt) {
    // Lay the regions out one after another, each at least its capacity.
    std::uint64_t vertices = 0;
    for (std::size_t d = 0; d < scene.draws().size(); ++d)
      for (PrepassList list : kCapturedLists) {
        const std::size_t r = region(d, list);
        const std::uint64_t patches = prepass.command(d, list).indexCount / 3;
        capacity_[r] = std::max({capacity_[r], patches * kFirstTrianglesPerPatch,
                                 std::uint64_t{1}});
        ranges_[r].firstVertex = static_cast<std::uint32_t>(vertices);
        vertices += 3 * capacity_[r];
      }
    const VkDeviceSize bytes = vertices * sizeof(CapturedVertex);
    if (vertices > std::numeric_limits<std::uint32_t>::max())
      throw Error(ErrorCode::DeviceUnsupported,
                  "the once-a-frame warp capture needs " + std::to_string(vertices) +
                      " vertices, more than the device's buffers hold; render with "
                      "VulkanOptions::warpOncePerFrame off");
    if (buffer_.size() < bytes)
      buffer_ = Buffer(context_, bytes + bytes / 4,
                       VK_BUFFER_USAGE_TRANSFORM_FEEDBACK_BUFFER_BIT_EXT |
                           VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                       BufferMemory::Device);
    split_->bind(buffer_.get(), buffer_.size() / (3 * sizeof(CapturedVertex)),
                 static_cast<std::uint32_t>(regions));
    context_.submitAndWait([&](VkCommandBuffer cmd) {
      stopwatch.start(cmd);
      record(cmd, scene, prepass, frameSet, warpSet, captureView, snapToRim, splitTornPieces);
      stopwatch.stop(cmd);
    });
    ++captures_;
    const std::optional<double> seconds = stopwatch.seconds();
    if (seconds) gpuSeconds = gpuSeconds.value_or(0.0) + *seconds;
    // Per query: primitives written, primitives needed.
    std::vector<std::uint64_t> counts(2 * regions, 0);
    if (regions > 0)
      check(vkGetQueryPoolResults(context_.device(), queries_.get(), 0,
                                  static_cast<std::uint32_t>(regions),
                                  counts.size() * sizeof(std::uint64_t), counts.data(),
                                  2 * sizeof(std::uint64_t),
                                  VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
            "vkGetQueryPoolResults");
    bool overflowed = false;
    for (std::size_t r = 0; r < regions; ++r) {
      const std::uint64_t written = counts[2 * r], needed = counts[2 * r + 1];
      ranges_[r].vertexCount = static_cast<std::uint32_t>(3 * written);
      if (needed > capacity_[r]) overflowed = true;
      // Room for the next frames' needs to grow a little without a second capture.
      capacity_[r] = std::max(capacity_[r], needed + needed / 4);
    }
    if (!overflowed) return gpuSeconds;
  }
  throw Error(ErrorCode::Internal,
              "the once-a-frame warp capture overflowed its buffer twice (the transform "
              "feedback's needs changed between two identical captures)");
}

void WarpCapture::record(VkCommandBuffer cmd, const GpuScene& scene,
                         const ConformalPrepass& prepass, VkDescriptorSet frameSet,
                         VkDescriptorSet warpSet, std::uint32_t captureView, bool snapToRim,
                         bool splitTornPieces) {
  const std::uint32_t regions = static_cast<std::uint32_t>(2 * scene.draws().size());
  if (regions > 0) vkCmdResetQueryPool(cmd, queries_.get(), 0, regions);
  const Pipelines::Capture& capture = pipelines_.capture();
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = capture.renderPass.get();
  begin.framebuffer = capture.framebuffer.get();
  begin.renderArea = {{0, 0}, {1, 1}};
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  const VkPipelineLayout layout = pipelines_.layout();
  const std::array<VkDescriptorSet, 2> sets = {frameSet, warpSet};
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 2, sets.data(), 0,
                          nullptr);
  const VkBuffer buffer = buffer_.get();
  for (PrepassList list : kCapturedLists) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS,
                      list == PrepassList::Tessellated ? capture.tessellated.get()
                                                       : capture.dropping.get());
    for (std::size_t d = 0; d < scene.draws().size(); ++d) {
      const std::uint32_t r = static_cast<std::uint32_t>(region(d, list));
      const VkDrawIndexedIndirectCommand c = prepass.command(d, list);
      // The query is written even for an empty list (zero primitives).
      const VkDeviceSize offset = VkDeviceSize{ranges_[r].firstVertex} * sizeof(CapturedVertex);
      const VkDeviceSize size = capacity_[r] * 3 * sizeof(CapturedVertex);
      bindBuffers_(cmd, 0, 1, &buffer, &offset, &size);
      beginQuery_(cmd, queries_.get(), r, 0, 0);
      begin_(cmd, 0, 0, nullptr, nullptr);
      if (c.indexCount > 0) {
        const GpuScene::Draw& draw = scene.draws()[d];
        const PushConstants push{draw.baseColorFactor, captureView, draw.hasNormals ? 1u : 0u,
                                 c.vertexOffset};
        vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_ALL_GRAPHICS, 0, sizeof(push), &push);
        vkCmdDraw(cmd, c.indexCount, 1, c.firstIndex, 0);
      }
      end_(cmd, 0, 0, nullptr, nullptr);
      endQuery_(cmd, queries_.get(), r, 0);
    }
  }
  vkCmdEndRenderPass(cmd);
  std::vector<CapturedCutSplit::Region> dropping;
  for (std::size_t d = 0; d < scene.draws().size(); ++d) {
    const std::uint32_t r = static_cast<std::uint32_t>(region(d, PrepassList::Dropping));
    if (prepass.command(d, PrepassList::Dropping).indexCount > 0)
      dropping.push_back({ranges_[r].firstVertex / 3, static_cast<std::uint32_t>(capacity_[r]), r});
  }
  if (splitTornPieces)
    split_->record(cmd, queries_.get(), regions, dropping, frameSet, warpSet, snapToRim);
  // The walls' draws read the buffer as vertices (in later submissions).
  VkMemoryBarrier written{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  written.srcAccessMask = VK_ACCESS_TRANSFORM_FEEDBACK_WRITE_BIT_EXT | VK_ACCESS_SHADER_WRITE_BIT;
  written.dstAccessMask = VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT;
  vkCmdPipelineBarrier(cmd,
                       VK_PIPELINE_STAGE_TRANSFORM_FEEDBACK_BIT_EXT |
                           VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                       VK_PIPELINE_STAGE_VERTEX_INPUT_BIT, 0, 1, &written, 0, nullptr, 0,
                       nullptr);
}

}  // namespace confvis::vulkan
