#include "frame_renderer.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <functional>
#include <string_view>

#include "confvis/backends/conformal_warp.hpp"
#include "confvis/backends/vulkan/warp_interface.hpp"
#include "confvis/base/stopwatch.hpp"
#include "map_images.hpp"
#include "vk_check.hpp"

namespace confvis::vulkan {
namespace {

// The view the once-a-frame capture draws through (warp_capture.hpp): an identity projection, so
// that the captured positions are the warped physical points; the walls' strictest cut gap (the
// geometry shader's minGap; the pre-pass takes the same) and bend bound; params.w + 4: warp.tesc
// culls by no view. None where the frame is not tessellated (params.w = 0).
std::optional<ViewData> captureViewOf(const FramePlan& plan) {
  if (!plan.warpOncePerFrame || plan.views.empty() || plan.views.front().params.w == 0.0f)
    return std::nullopt;
  ViewData capture;
  capture.viewProj = glm::mat4(1.0f);
  capture.eyeVirtual = glm::vec4(0.0f);
  capture.params = plan.views.front().params;
  for (const ViewData& view : plan.views) {
    capture.params.x = std::min(capture.params.x, view.params.x);
    capture.params.z = std::min(capture.params.z, view.params.z);
  }
  capture.params.w += 4.0f;
  return capture;
}

bool operator==(const ViewData& a, const ViewData& b) {
  return a.viewProj == b.viewProj && a.eyeVirtual == b.eyeVirtual && a.params == b.params;
}

}  // namespace

FrameRenderer::FrameRenderer(VulkanContext& context, Pipelines& pipelines,
                             bool timePrepassPasses)
    : context_(context), pipelines_(pipelines), prepass_(context, pipelines), stopwatch_(context),
      timePrepassPasses_(timePrepassPasses), flatCull_(context, pipelines) {
  const VkDevice device = context.device();
  FrameDescriptors made = allocateFrameDescriptors(context, pipelines);
  pool_ = std::move(made.pool);
  frameSet_ = made.frameSet;
  warpSet_ = made.warpSet;
  frameBuffer_ = std::move(made.frameUniforms);
  const VkSamplerCreateInfo samplerInfo = warpSamplerInfo();
  VkSampler sampler = VK_NULL_HANDLE;
  check(vkCreateSampler(device, &samplerInfo, nullptr, &sampler), "vkCreateSampler");
  warpSampler_ = UniqueSampler(device, sampler);
  if (context.transformFeedback()) capture_ = std::make_unique<WarpCapture>(context, pipelines);
}

FrameRenderer::Targets& FrameRenderer::targets(std::uint32_t width, std::uint32_t height,
                                               std::uint32_t views, VkRenderPass renderPass) {
  const auto key = std::make_tuple(width, height, views);
  auto found = targets_.find(key);
  if (found != targets_.end()) return found->second;
  Targets t;
  ImageSpec color;
  color.format = kColorFormat;
  color.width = width;
  color.height = height;
  color.layers = views;
  color.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  t.color = Image(context_, color);
  ImageSpec depth = color;
  depth.format = kDepthFormat;
  depth.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
  depth.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
  t.depth = Image(context_, depth);
  const std::array<VkImageView, 2> attachments = {t.color.view(), t.depth.view()};
  VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  info.renderPass = renderPass;
  info.attachmentCount = 2;
  info.pAttachments = attachments.data();
  info.width = width;
  info.height = height;
  info.layers = 1;  // multiview: the view mask picks the layers
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  check(vkCreateFramebuffer(context_.device(), &info, nullptr, &framebuffer),
        "vkCreateFramebuffer");
  t.framebuffer = UniqueFramebuffer(context_.device(), framebuffer);
  t.readback = Buffer(context_, std::size_t{width} * height * views * 4 * sizeof(float),
                      VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
  return targets_.emplace(key, std::move(t)).first->second;
}

void FrameRenderer::uploadFrame(const FramePlan& plan, const std::optional<ViewData>& captureView) {
  std::memcpy(frameBuffer_.mapped(), &plan.frame, sizeof(FrameUniforms));
  // The capture's view after the walls' (FrameRenderer::captureWarp).
  const std::size_t bytes = (plan.views.size() + 1) * sizeof(ViewData);
  if (viewBuffer_.size() < bytes) {
    viewBuffer_ = Buffer(context_, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, BufferMemory::Shared);
    writeBufferDescriptor(context_.device(), frameSet_, 1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                          viewBuffer_.get());
  }
  std::memcpy(viewBuffer_.mapped(), plan.views.data(), plan.views.size() * sizeof(ViewData));
  const ViewData unused{};
  std::memcpy(static_cast<char*>(viewBuffer_.mapped()) + plan.views.size() * sizeof(ViewData),
              captureView ? &*captureView : &unused, sizeof(ViewData));
}

void FrameRenderer::uploadMap(const RetargetMap& map) {
  // Every frame passes its map: the hash of its texels tells whether the upload is still current
  // (validating and converting a 256^2 map each frame cost ~5 ms, 5-10 % of a 20k-triangle
  // conformal frame on lavapipe).
  const std::uint64_t hash = fingerprintCubeMap(
      map.geom, glm::dvec3(map.reference.x, map.reference.y, map.reference.z));
  if (geomMap_.get() != VK_NULL_HANDLE && hash == mapHash_) return;
  // The ray map goes with it (the pre-pass's rim: where its alpha ends): a map is told by its
  // geom texels and reference point, as the bake makes both maps together.
  MapImages images = uploadMapImages(context_, map);  // validates the map
  geomMap_ = std::move(images.geom);
  coverageMap_ = std::move(images.coverage);
  writeImageDescriptor(context_.device(), warpSet_, kWarpBinding, warpSampler_.get(),
                       geomMap_.view());
  writeImageDescriptor(context_.device(), warpSet_, kCoverageBinding, warpSampler_.get(),
                       coverageMap_.view());
  mapHash_ = hash;
}

void FrameRenderer::recordPass(VkCommandBuffer cmd, const PassRequest& request,
                               const GpuScene& scene, const Targets& t) {
  const std::uint32_t width = request.width, height = request.height, views = request.views;
  const Pipelines::Pass& pass = pipelines_.pass(views);
  std::array<VkClearValue, 2> clear{};
  clear[0].color = {{0.0f, 0.0f, 0.0f, 0.0f}};  // alpha 0 where nothing is drawn
  clear[1].depthStencil = {0.0f, 0};  // reverse-Z: 0 is infinitely far
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = pass.renderPass.get();
  begin.framebuffer = t.framebuffer.get();
  begin.renderArea = {{0, 0}, {width, height}};
  begin.clearValueCount = 2;
  begin.pClearValues = clear.data();
  stopwatch_.start(cmd);
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  const VkViewport viewport{0.0f, 0.0f, float(width), float(height), 0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, {width, height}};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  recordDraws(cmd, pass, request, scene);
  vkCmdEndRenderPass(cmd);
  stopwatch_.stop(cmd);
  if (!request.readback) return;
  // The pass left the colour layers in TRANSFER_SRC_OPTIMAL; its dependency orders this copy.
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, views};
  region.imageExtent = {width, height, 1};
  vkCmdCopyImageToBuffer(cmd, t.color.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                         t.readback.get(), 1, &region);
  // Make the copy visible to the host reading the mapped buffer after the fence.
  VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                       &toHost, 0, nullptr, 0, nullptr);
}

void FrameRenderer::recordDraws(VkCommandBuffer cmd, const Pipelines::Pass& pass,
                                const PassRequest& request, const GpuScene& scene) {
  const VkPipelineLayout layout = pipelines_.layout();
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &frameSet_, 0,
                          nullptr);
  if (request.conformal)
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, kWarpDescriptorSet, 1,
                            &warpSet_, 0, nullptr);
  // Plain and conformal flat; the other conformal vertex shaders read their vertices themselves.
  const std::array<VkBuffer, 2> vertexBuffers = {scene.vertexBuffer(), prepass_.warped()};
  const std::array<VkDeviceSize, 2> offsets = {0, 0};
  vkCmdBindVertexBuffers(cmd, 0, request.conformal ? 2 : 1, vertexBuffers.data(), offsets.data());
  // Tessellated lists: one draw each, without an index buffer (warp.vert reads the list); the
  // pre-pass has finished (the frame waited for it), so the host knows where the list lies.
  const auto drawPatches = [&](PushConstants push, const VkDrawIndexedIndirectCommand& c) {
    push.vertexOffset = c.vertexOffset;
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_ALL_GRAPHICS, 0, sizeof(push), &push);
    if (c.indexCount > 0) vkCmdDraw(cmd, c.indexCount, 1, c.firstIndex, 0);
  };
  // Draw d's material and push constants, bound; the constants returned for the patch lists.
  const auto bindMaterial = [&](std::size_t d) {
    const GpuScene::Draw& draw = scene.draws()[d];
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 2, 1, &draw.material,
                            0, nullptr);
    const PushConstants push{draw.baseColorFactor, request.viewBase, draw.hasNormals ? 1u : 0u,
                             0};
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_ALL_GRAPHICS, 0, sizeof(push), &push);
    return push;
  };
  const auto drawAll = [&](VkPipeline pipeline, VkBuffer indices, PrepassList list) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    if (indices != VK_NULL_HANDLE) vkCmdBindIndexBuffer(cmd, indices, 0, VK_INDEX_TYPE_UINT32);
    for (std::size_t d = 0; d < scene.draws().size(); ++d) {
      const GpuScene::Draw& draw = scene.draws()[d];
      const PushConstants push = bindMaterial(d);
      if (!request.conformal)
        vkCmdDrawIndexed(cmd, draw.indexCount, 1, draw.firstIndex, draw.vertexOffset, 0);
      else if (list == PrepassList::Flat || list == PrepassList::Pieces)  // its list and count
        vkCmdDrawIndexedIndirect(cmd, prepass_.commands(), ConformalPrepass::commandOffset(d, list),
                                 1, sizeof(VkDrawIndexedIndirectCommand));
      else
        drawPatches(push, prepass_.command(d, list));
    }
  };
  if (!request.conformal) {
    drawAll(pass.plain.get(), scene.indexBuffer(), PrepassList::Flat);
    return;
  }
  if (flatCulled_) {  // the wall's own flat list (flat_wall_cull.hpp)
    const std::uint32_t wall = request.viewBase / cullEyes_;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.conformalFlat.get());
    vkCmdBindIndexBuffer(cmd, flatCull_.indices(), 0, VK_INDEX_TYPE_UINT32);
    for (std::size_t d = 0; d < scene.draws().size(); ++d) {
      bindMaterial(d);
      vkCmdDrawIndexedIndirect(cmd, flatCull_.commands(), flatCull_.commandOffset(wall, d), 1,
                               sizeof(VkDrawIndexedIndirectCommand));
    }
  } else {
    drawAll(pass.conformalFlat.get(), prepass_.flatIndices(), PrepassList::Flat);
  }
  // The pieces index the edge midpoints and cut vertices after the scene's (GpuScene's layout).
  drawAll(pass.conformalFlat.get(), prepass_.pieceIndices(), PrepassList::Pieces);
  if (drawCaptured_) {
    drawCaptured(cmd, request, scene);
    return;
  }
  drawAll(pass.conformalTessellated.get(), VK_NULL_HANDLE, PrepassList::Tessellated);
  drawAll(pass.conformalDropping.get(), VK_NULL_HANDLE, PrepassList::Dropping);
}

void FrameRenderer::drawCaptured(VkCommandBuffer cmd,
                                 const PassRequest& request, const GpuScene& scene) {
  const VkPipelineLayout layout = pipelines_.layout();
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines_.capturedDraw(request.views));
  const VkBuffer buffer = capture_->buffer();
  const VkDeviceSize offset = 0;
  vkCmdBindVertexBuffers(cmd, 0, 1, &buffer, &offset);
  // The lists in the per-wall path's order: the tessellated ones, then those through the
  // geometry shader.
  for (PrepassList list : {PrepassList::Tessellated, PrepassList::Dropping})
    for (std::size_t d = 0; d < scene.draws().size(); ++d) {
      const WarpCapture::Range range = capture_->range(d, list);
      if (range.vertexCount == 0) continue;
      const GpuScene::Draw& draw = scene.draws()[d];
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 2, 1, &draw.material,
                              0, nullptr);
      const PushConstants push{draw.baseColorFactor,
                               (request.viewBase + capturedViewShift_) % viewCount_,
                               draw.hasNormals ? 1u : 0u, 0};
      vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_ALL_GRAPHICS, 0, sizeof(push), &push);
      vkCmdDraw(cmd, range.vertexCount, 1, range.firstVertex, 0);
    }
}

std::vector<ImageRGBA> FrameRenderer::renderPass(const PassRequest& request,
                                                 const GpuScene& scene) {
  const VkRenderPass renderPass = pipelines_.pass(request.views).renderPass.get();
  const Targets& t = targets(request.width, request.height, request.views, renderPass);
  context_.submitAndWait([&](VkCommandBuffer cmd) { recordPass(cmd, request, scene, t); });
  addGpuSeconds(stopwatch_.seconds());
  std::vector<ImageRGBA> layers;
  for (std::uint32_t layer = 0; layer < request.views; ++layer)
    layers.push_back(layerToImage(t.readback, request.width, request.height, layer));
  return layers;
}

void FrameRenderer::addGpuSeconds(std::optional<double> seconds) {
  if (gpuSeconds_ && seconds) *gpuSeconds_ += *seconds;
}

FrameRenderer::PrepassCounts FrameRenderer::prepassCounts(const GpuScene& scene) const {
  PrepassCounts counts;
  counts.seconds = prepassSeconds_;
  counts.gpuSeconds = prepassGpuSeconds_;
  if (prepassPassSeconds_.size() == ConformalPrepass::kPassNames.size())
    counts.passGpuSeconds = prepassPassSeconds_;
  counts.reused = prepassReused_;
  counts.splitAlongCut = prepass_.trianglesSplitAlongCut();
  if (flatCulled_)
    for (std::uint32_t wall = 0; wall < flatCull_.walls(); ++wall)
      counts.flatPerWall.push_back(flatCull_.wallTriangles(wall));
  for (std::size_t d = 0; d < scene.draws().size(); ++d) {
    counts.flat += prepass_.flatTriangles(d) +
                   prepass_.command(d, PrepassList::Pieces).indexCount / 3;
    counts.tessellated += prepass_.command(d, PrepassList::Tessellated).indexCount / 3;
    counts.dropping += prepass_.command(d, PrepassList::Dropping).indexCount / 3;
  }
  return counts;
}

std::vector<WallImage> FrameRenderer::render(const FramePlan& plan, const GpuScene& scene,
                                             const RetargetMap* map, bool multiview,
                                             Progress& progress) {
  prepareFrame(plan, scene, map);
  const bool conformal = map != nullptr;
  const auto eyes = static_cast<std::uint32_t>(plan.eyes.size());
  std::vector<WallImage> images;
  for (std::size_t wall = 0; wall < plan.walls.size(); ++wall) {
    PassRequest request{plan.widths[wall], plan.heights[wall],
                        static_cast<std::uint32_t>(wall) * eyes, eyes, conformal};
    std::vector<ImageRGBA> layers;
    if (multiview) {
      layers = renderPass(request, scene);  // every eye in one multiview pass
    } else {
      request.views = 1;
      for (std::uint32_t eye = 0; eye < eyes; ++eye, ++request.viewBase)
        layers.push_back(std::move(renderPass(request, scene).front()));
    }
    for (std::uint32_t eye = 0; eye < eyes; ++eye)
      images.push_back({plan.walls[wall]->name, plan.eyes[eye], std::move(layers[eye])});
    progress.advance();
  }
  return images;
}

void FrameRenderer::prepareFrame(const FramePlan& plan, const GpuScene& scene,
                                 const RetargetMap* map) {
  const bool conformal = map != nullptr;
  gpuSeconds_ = stopwatch_.available() ? std::optional<double>(0.0) : std::nullopt;
  if (conformal) uploadMap(*map);
  const std::optional<ViewData> captureView =
      conformal && capture_ ? captureViewOf(plan) : std::nullopt;
  uploadFrame(plan, captureView);
  drawCaptured_ = false;
  flatCulled_ = false;
  if (conformal) {
    std::vector<glm::vec4> viewParams;
    for (const ViewData& view : plan.views) viewParams.push_back(view.params);
    PrepassThresholds thresholds =
        prepassThresholds(viewParams, plan.errorWalls, plan.splitAlongCut, plan.snapCutToRim);
    thresholds.dropOutsideSourceField = plan.dropOutsideSourceField;
    const PrepassInputs inputs{scene.id(), mapHash_, plan.frame, thresholds};
    prepassReused_ = plan.reusePrepass && prepassCurrent_ && inputs == prepassInputs_;
    prepassSeconds_ = 0.0;
    prepassGpuSeconds_ = gpuSeconds_;  // 0 where reused
    prepassPassSeconds_.clear();
    if (!prepassReused_) {
      prepassCurrent_ = false;  // until the submission below has completed
      const auto start = SteadyClock::now();
      context_.submitAndWait([&](VkCommandBuffer cmd) {
        stopwatch_.start(cmd);
        prepass_.record(cmd, scene, frameSet_, warpSet_, thresholds,
                        timePrepassPasses_ ? &stopwatch_ : nullptr);
        stopwatch_.stop(cmd);
      });
      prepassSeconds_ = secondsSince(start);
      prepassGpuSeconds_ = stopwatch_.seconds(&prepassPassSeconds_);
      addGpuSeconds(prepassGpuSeconds_);
      prepassInputs_ = inputs;
      prepassCurrent_ = true;
    }
    // The walls' own flat lists, every frame: the frusta follow the head, which a reused
    // pre-pass does not see (flat_wall_cull.hpp).
    if (plan.cullFlatListPerWall) {
      cullEyes_ = static_cast<std::uint32_t>(plan.eyes.size());
      context_.submitAndWait([&](VkCommandBuffer cmd) {
        stopwatch_.start(cmd);
        flatCull_.record(cmd, scene, frameSet_, prepass_.flatIndices(), prepass_.warped(),
                         static_cast<std::uint32_t>(plan.walls.size()), cullEyes_,
                         plan.cullFlatListAgainstNextWallForTests);
        stopwatch_.stop(cmd);
      });
      addGpuSeconds(stopwatch_.seconds());
      flatCulled_ = true;
    }
    // warp.tesc reads the edge levels (set 0, binding 2), warp.vert the tessellated lists, the
    // scene's vertices and their warps (bindings 3-5); the set is idle now that the pre-pass has
    // completed.
    if (patchLevelsScene_ != prepass_.sceneId()) {
      patchLevelsScene_ = prepass_.sceneId();
      const std::array<VkBuffer, 4> buffers = {prepass_.patchLevels(),
                                               prepass_.tessellatedIndices(),
                                               scene.vertexBuffer(), prepass_.warped()};
      for (std::uint32_t i = 0; i < buffers.size(); ++i)
        writeBufferDescriptor(context_.device(), frameSet_, 2 + i,
                              VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffers[i]);
    }
    if (captureView) captureWarp(plan, scene, captureView);
  }
}

void FrameRenderer::captureWarp(const FramePlan& plan, const GpuScene& scene,
                                const std::optional<ViewData>& captureView) {
  viewCount_ = static_cast<std::uint32_t>(plan.views.size());
  capturedViewShift_ = static_cast<std::uint32_t>(
      (std::uint64_t{plan.capturedViewShiftForTests} * plan.eyes.size()) % viewCount_);
  // Reused with the pre-pass: the capture depends on nothing else but its view.
  if (!(prepassReused_ && captureCurrent_ && capturedThrough_ == *captureView)) {
    captureCurrent_ = false;  // until the capture below has completed
    addGpuSeconds(capture_->capture(scene, prepass_, frameSet_, warpSet_, viewCount_,
                                    plan.snapCutToRim, plan.splitCapturedTornPiecesForTests,
                                    stopwatch_));
    capturedThrough_ = *captureView;
    captureCurrent_ = true;
  }
  drawCaptured_ = true;
}

}  // namespace confvis::vulkan
