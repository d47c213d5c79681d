// FrameRenderer::renderToTargets: each wall's pass as for render(), then one blit per target
// from the float colour layer into the application's image instead of the readback copy.
#include <map>

#include "frame_renderer.hpp"
#include "vk_check.hpp"

namespace confvis::vulkan {
namespace {

// One blit, in the order the passes run, with whether it is its image's first or last write.
struct Blit {
  const VulkanImageTarget* target = nullptr;
  std::uint32_t pass = 0;         // index of the pass (submission) that writes it
  std::uint32_t sourceLayer = 0;  // the colour layer of that pass
  std::uint32_t width = 0, height = 0;  // of the rendered wall
  bool first = false, last = false;
};

void barrier(VkCommandBuffer cmd, const VulkanImageTarget& target, VkImageLayout from,
             VkImageLayout to, VkAccessFlags srcAccess, VkAccessFlags dstAccess,
             VkPipelineStageFlags srcStage, VkPipelineStageFlags dstStage) {
  VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  b.oldLayout = from;
  b.newLayout = to;
  b.srcAccessMask = srcAccess;
  b.dstAccessMask = dstAccess;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = target.image;
  b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, target.layer, 1};
  vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &b);
}

VkRect2D regionOf(const VulkanImageTarget& target) {
  if (target.region.extent.width == 0 && target.region.extent.height == 0)
    return {{0, 0}, target.extent};
  return target.region;
}

void recordBlit(VkCommandBuffer cmd, const Blit& blit, VkImage source) {
  const VulkanImageTarget& target = *blit.target;
  if (blit.first)
    barrier(cmd, target, target.layoutBefore, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
            VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
            VK_PIPELINE_STAGE_TRANSFER_BIT);
  else  // another eye already went into this image: order the writes
    barrier(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
            VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT,
            VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
            VK_PIPELINE_STAGE_TRANSFER_BIT);
  const VkRect2D region = regionOf(target);
  VkImageBlit b{};
  b.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, blit.sourceLayer, 1};
  b.srcOffsets[1] = {static_cast<std::int32_t>(blit.width), static_cast<std::int32_t>(blit.height),
                     1};
  b.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, target.layer, 1};
  b.dstOffsets[0] = {region.offset.x, region.offset.y, 0};
  b.dstOffsets[1] = {region.offset.x + static_cast<std::int32_t>(region.extent.width),
                     region.offset.y + static_cast<std::int32_t>(region.extent.height), 1};
  // Pixel for pixel where the sizes match: the values exactly as rendered (then converted).
  const bool sameSize = region.extent.width == blit.width && region.extent.height == blit.height;
  vkCmdBlitImage(cmd, source, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target.image,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &b,
                 sameSize ? VK_FILTER_NEAREST : VK_FILTER_LINEAR);
  if (!blit.last) return;
  const bool present = target.layoutAfter == VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
  barrier(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, target.layoutAfter,
          VK_ACCESS_TRANSFER_WRITE_BIT,
          present ? 0 : VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT,
          VK_PIPELINE_STAGE_TRANSFER_BIT,
          present ? VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT : VK_PIPELINE_STAGE_ALL_COMMANDS_BIT);
}

}  // namespace

void FrameRenderer::renderToTargets(const FramePlan& plan, const GpuScene& scene,
                                    const RetargetMap* map, bool multiview,
                                    const std::vector<VulkanImageTarget>& outputs,
                                    Progress& progress) {
  prepareFrame(plan, scene, map);
  const bool conformal = map != nullptr;
  const auto eyes = static_cast<std::uint32_t>(plan.eyes.size());

  // The passes in the order render() runs them, and the blits each one feeds.
  std::vector<PassRequest> passes;
  std::vector<Blit> blits;
  for (std::uint32_t wall = 0; wall < plan.walls.size(); ++wall) {
    PassRequest request{plan.widths[wall], plan.heights[wall], wall * eyes,
                        multiview ? eyes : 1u, conformal, false};
    for (std::uint32_t eye = 0; eye < eyes; ++eye) {
      if (eye == 0 || !multiview) {
        passes.push_back(request);
        ++request.viewBase;
      }
      for (const VulkanImageTarget& target : outputs)
        if (target.wall == plan.walls[wall]->name && target.eye == plan.eyes[eye])
          blits.push_back({&target, static_cast<std::uint32_t>(passes.size() - 1),
                           multiview ? eye : 0u, request.width, request.height});
    }
  }
  std::map<VkImage, std::size_t> firstOf, lastOf;
  for (std::size_t i = 0; i < blits.size(); ++i) {
    firstOf.try_emplace(blits[i].target->image, i);
    lastOf[blits[i].target->image] = i;
  }
  for (const auto& [image, i] : firstOf) blits[i].first = true;
  for (const auto& [image, i] : lastOf) blits[i].last = true;

  std::size_t nextBlit = 0;
  for (std::uint32_t p = 0; p < passes.size(); ++p) {
    const PassRequest& request = passes[p];
    const VkRenderPass renderPass = pipelines_.pass(request.views).renderPass.get();
    const Targets& t = targets(request.width, request.height, request.views, renderPass);
    // An image's semaphores go with the submissions of its first and last blit: a semaphore
    // wait orders only its own batch (at the transfer stage: the drawing need not wait); later
    // blits into the image follow through their barriers.
    const std::size_t from = nextBlit;
    std::size_t to = from;
    while (to < blits.size() && blits[to].pass == p) ++to;
    std::vector<VkSemaphore> wait, signal;
    for (std::size_t b = from; b < to; ++b) {
      if (blits[b].first && blits[b].target->waitSemaphore)
        wait.push_back(blits[b].target->waitSemaphore);
      if (blits[b].last && blits[b].target->signalSemaphore)
        signal.push_back(blits[b].target->signalSemaphore);
    }
    context_.submitAndWait(
        [&](VkCommandBuffer cmd) {
          recordPass(cmd, request, scene, t);
          for (std::size_t b = from; b < to; ++b) recordBlit(cmd, blits[b], t.color.get());
        },
        wait, signal);
    nextBlit = to;
    addGpuSeconds(stopwatch_.seconds());
    if (multiview || (p + 1) % eyes == 0) progress.advance();  // a wall is done
  }
}

}  // namespace confvis::vulkan
