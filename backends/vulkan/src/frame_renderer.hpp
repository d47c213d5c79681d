#pragma once
// Per-frame work: offscreen colour + depth targets per wall size (one layer per eye), the frame's
// uniform and view buffers, the geom cube map, command recording (all eyes of a wall in one
// multiview pass), submission and readback into images.
#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <tuple>
#include <vector>

#include "confvis/backends/render_backend.hpp"
#include "confvis/backends/vulkan/external_device.hpp"
#include "confvis/base/progress.hpp"
#include "conformal_prepass.hpp"
#include "flat_wall_cull.hpp"
#include "frame_plan.hpp"
#include "gpu_stopwatch.hpp"
#include "gpu_scene.hpp"
#include "memory.hpp"
#include "pipelines.hpp"
#include "warp_capture.hpp"

namespace confvis::vulkan {

class FrameRenderer {
 public:
  // timePrepassPasses: timestamps between the pre-pass's passes (PrepassCounts::passGpuSeconds).
  FrameRenderer(VulkanContext& context, Pipelines& pipelines, bool timePrepassPasses = false);

  // Renders every wall of `plan` (conformal when `map` is non-null), returning images in wall
  // order then eye order. multiview: all eyes of a wall in one pass (VK_KHR_multiview);
  // otherwise one pass per eye (see multiview_probe.hpp for why that exists).
  std::vector<WallImage> render(const FramePlan& plan, const GpuScene& scene,
                                const RetargetMap* map, bool multiview, Progress& progress);

  // The same frame written into application images instead of read back
  // (frame_renderer_targets.cpp; external_device.hpp says what a target must be). Every target
  // names a wall of the plan and one of its eyes (the caller checks).
  void renderToTargets(const FramePlan& plan, const GpuScene& scene, const RetargetMap* map,
                       bool multiview, const std::vector<VulkanImageTarget>& outputs,
                       Progress& progress);

  // Triangles the last conformal frame drew flat and through tessellation (the pre-pass's lists).
  struct PrepassCounts {
    std::size_t flat = 0, tessellated = 0;  // tessellated: without the geometry shader
    std::size_t dropping = 0;               // tessellated with the geometry shader
    std::size_t splitAlongCut = 0;          // drawn in flat pieces up to the cut
    double seconds = 0.0;  // wall-clock time of the pre-pass submission (0 where reused)
    std::optional<double> gpuSeconds;  // its GPU time (0 where reused; none without timestamps)
    bool reused = false;   // the previous conformal frame's pre-pass was still current
    // Each pass's GPU time (ConformalPrepass::kPassNames' order) where the passes were timed.
    std::vector<double> passGpuSeconds;
    // Per wall: the flat-list triangles its pass drew (empty where the per-wall cull is off).
    std::vector<std::uint64_t> flatPerWall;
  };
  PrepassCounts prepassCounts(const GpuScene& scene) const;

  // GPU time of the last frame: its pre-pass and every wall's render pass, without the copies
  // for readback; nullopt where the queue writes no timestamps.
  std::optional<double> gpuSeconds() const { return gpuSeconds_; }

 private:
  struct Targets {
    Image color, depth;
    UniqueFramebuffer framebuffer;
    Buffer readback;
  };
  Targets& targets(std::uint32_t width, std::uint32_t height, std::uint32_t views,
                   VkRenderPass renderPass);
  void uploadFrame(const FramePlan& plan, const std::optional<ViewData>& captureView);
  // The once-a-frame capture of the tessellated lists (warp_capture.hpp), where the device and
  // the plan have it; else the walls' draws tessellate themselves.
  void captureWarp(const FramePlan& plan, const GpuScene& scene,
                   const std::optional<ViewData>& captureView);

  // The map and frame uploads and the conformal pre-pass, before any wall's pass.
  void prepareFrame(const FramePlan& plan, const GpuScene& scene, const RetargetMap* map);
  void addGpuSeconds(std::optional<double> seconds);
  void uploadMap(const RetargetMap& map);
  struct PassRequest {
    std::uint32_t width, height;
    std::uint32_t viewBase;  // index into FramePlan::views of the pass's view 0
    std::uint32_t views;     // multiview layers drawn in the pass
    bool conformal;
    bool readback = true;  // copy the colour layers into the readback buffer after the pass
  };
  // Draws one pass, reads it back; one image per view.
  std::vector<ImageRGBA> renderPass(const PassRequest& request, const GpuScene& scene);
  void recordPass(VkCommandBuffer cmd, const PassRequest& request, const GpuScene& scene,
                  const Targets& targets);
  void recordDraws(VkCommandBuffer cmd, const Pipelines::Pass& pass, const PassRequest& request,
                   const GpuScene& scene);
  void drawCaptured(VkCommandBuffer cmd, const PassRequest& request,
                    const GpuScene& scene);

  VulkanContext& context_;
  Pipelines& pipelines_;
  std::map<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>, Targets> targets_;
  Buffer frameBuffer_, viewBuffer_;
  UniqueDescriptorPool pool_;
  std::uint64_t patchLevelsScene_ = 0;  // scene whose pre-pass buffers frameSet_ binding 2 holds
  VkDescriptorSet frameSet_ = VK_NULL_HANDLE, warpSet_ = VK_NULL_HANDLE;
  Image geomMap_, coverageMap_;  // coverageMap_: the ray map (its alpha: the display's coverage)
  UniqueSampler warpSampler_;
  std::uint64_t mapHash_ = 0;
  // What the pre-pass read, for telling whether the last one is still current: the warp depends
  // on the scene, the map, the navigation (virtual to physical) and the error bounds, but not on
  // the head or the eyes.
  struct PrepassInputs {
    std::uint64_t scene = 0, map = 0;
    FrameUniforms frame{};
    PrepassThresholds thresholds{};
    bool operator==(const PrepassInputs&) const = default;
  };
  bool prepassCurrent_ = false;  // prepassInputs_ describe what the pre-pass's buffers hold
  PrepassInputs prepassInputs_;
  ConformalPrepass prepass_;
  double prepassSeconds_ = 0.0;
  std::optional<double> prepassGpuSeconds_, gpuSeconds_;
  GpuStopwatch stopwatch_;
  bool timePrepassPasses_ = false;
  std::vector<double> prepassPassSeconds_;  // empty unless timed and run this frame
  bool prepassReused_ = false;
  std::unique_ptr<WarpCapture> capture_;  // null without transform feedback
  bool drawCaptured_ = false;   // this frame's walls draw the capture's buffer
  bool captureCurrent_ = false;  // the buffer holds the current pre-pass's lists...
  ViewData capturedThrough_{};   // ...as drawn through this view
  std::uint32_t viewCount_ = 0, capturedViewShift_ = 0;  // plan.views.size(), in views
  FlatWallCull flatCull_;
  bool flatCulled_ = false;       // this frame's walls draw the per-wall flat lists...
  std::uint32_t cullEyes_ = 1;    // ...of views[wall * cullEyes_ + eye]
};

}  // namespace confvis::vulkan
