#include "confvis/backends/vulkan_backend.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <optional>

#include "confvis/backends/render_plan.hpp"
#include "confvis/backends/vulkan/external_device.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/progress.hpp"
#include "confvis/base/stopwatch.hpp"
#include "context.hpp"
#include "frame_plan.hpp"
#include "frame_renderer.hpp"
#include "gpu_scene.hpp"
#include "multiview_probe.hpp"
#include "pipelines.hpp"
#include "wide_triangle_split.hpp"

namespace confvis {
namespace {

using vulkan::DeviceCapabilities;

std::string versionString(std::uint32_t version) {
  return std::to_string(VK_API_VERSION_MAJOR(version)) + "." +
         std::to_string(VK_API_VERSION_MINOR(version)) + "." +
         std::to_string(VK_API_VERSION_PATCH(version));
}

void checkOptions(const VulkanOptions& options) {
  if (!(options.tessellationErrorPixels > 0.0) || !std::isfinite(options.tessellationErrorPixels))
    throw Error(ErrorCode::InvalidInput, "Vulkan backend: tessellation error must be > 0 pixels");
  if (!(options.maxSegmentDegrees > 0.0) || !(options.maxSegmentDegrees <= 180.0))
    throw Error(ErrorCode::InvalidInput,
                "Vulkan backend: the longest segment must be in (0, 180] degrees");
}

// The settings renderImages renders with: the targets' walls and eyes (see external_device.hpp).
RenderSettings settingsForTargets(const DisplayConfig& config, const RenderSettings& settings,
                                  const std::vector<VulkanImageTarget>& targets,
                                  VkPhysicalDevice physicalDevice) {
  if (targets.empty())
    throw Error(ErrorCode::InvalidInput, "Vulkan renderImages: no target image given");
  RenderSettings chosen = settings;
  chosen.walls.clear();
  chosen.eyes.clear();
  std::map<VkImage, const VulkanImageTarget*> byImage;
  for (const VulkanImageTarget& target : targets) {
    const std::string culprit = "Vulkan render target of wall '" + target.wall + "' (" +
                                eyeName(target.eye) + " eye): ";
    config.wall(target.wall);  // Error(InvalidInput) naming an unknown wall
    if (std::find(settings.eyes.begin(), settings.eyes.end(), target.eye) == settings.eyes.end())
      throw Error(ErrorCode::InvalidInput, culprit + "the settings do not render that eye");
    if (target.image == VK_NULL_HANDLE) throw Error(ErrorCode::InvalidInput, culprit + "no image");
    const VkRect2D r = target.region.extent.width == 0 && target.region.extent.height == 0
                           ? VkRect2D{{0, 0}, target.extent}
                           : target.region;
    if (r.extent.width == 0 || r.extent.height == 0 || r.offset.x < 0 || r.offset.y < 0 ||
        std::uint64_t(r.offset.x) + r.extent.width > target.extent.width ||
        std::uint64_t(r.offset.y) + r.extent.height > target.extent.height)
      throw Error(ErrorCode::InvalidInput,
                  culprit + "the region is empty or leaves the " +
                      std::to_string(target.extent.width) + "x" +
                      std::to_string(target.extent.height) + " image");
    VkFormatProperties properties;
    vkGetPhysicalDeviceFormatProperties(physicalDevice, target.format, &properties);
    if (!(properties.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_DST_BIT))
      throw Error(ErrorCode::InvalidInput, culprit + "the device cannot blit into format " +
                                               std::to_string(target.format));
    const auto [other, fresh] = byImage.try_emplace(target.image, &target);
    if (!fresh && (other->second->layoutBefore != target.layoutBefore ||
                   other->second->layoutAfter != target.layoutAfter ||
                   other->second->waitSemaphore != target.waitSemaphore ||
                   other->second->signalSemaphore != target.signalSemaphore))
      throw Error(ErrorCode::InvalidInput,
                  culprit + "shares its image with wall '" + other->second->wall +
                      "' but not its layouts and semaphores");
    if (std::find(chosen.walls.begin(), chosen.walls.end(), target.wall) == chosen.walls.end())
      chosen.walls.push_back(target.wall);
  }
  for (Eye eye : settings.eyes)
    for (const VulkanImageTarget& target : targets)
      if (target.eye == eye) {
        chosen.eyes.push_back(eye);
        break;
      }
  return chosen;
}

// A scene with its too-wide triangles split, and its upload. At namespace scope: clang 14 cannot
// default-construct, inside std::optional, a nested struct with default member initializers.
struct SplitScene {
  Scene scene;
  std::optional<vulkan::GpuScene> gpu;
  std::size_t trianglesSplit = 0;
};

class VulkanBackend final : public VulkanRenderer {
 public:
  explicit VulkanBackend(const VulkanOptions& options)
      : VulkanBackend(options, std::make_unique<vulkan::VulkanContext>(vulkan::ContextOptions{
                                   options.device, options.validation,
                                   options.onValidationMessage})) {}
  VulkanBackend(const VulkanOptions& options, const VulkanDeviceHandles& device)
      : VulkanBackend(options, std::make_unique<vulkan::VulkanContext>(device)) {}

  std::string name() const override { return "vulkan"; }

  VulkanDeviceHandles deviceHandles() const override { return context_->handles(); }

  void setScene(const Scene& scene) override {
    scene_.reset();  // free the old buffers first
    split_.reset();
    checkedCentre_.reset();
    scene_.emplace(*context_, pipelines_, scene);
    source_ = scene;
  }

  RenderResult render(const DisplayConfig& config, const RetargetMap* map,
                      const RenderSettings& settings) override {
    RenderResult result;
    result.stats = renderFrame(config, map, settings, [&](const Frame& frame) {
      result.images =
          frames_.render(frame.plan, frame.drawn, frame.map, multiview_, frame.progress);
    });
    return result;
  }

  FrameStats renderImages(const DisplayConfig& config, const RetargetMap* map,
                          const RenderSettings& settings,
                          const std::vector<VulkanImageTarget>& targets) override {
    const RenderSettings chosen =
        settingsForTargets(config, settings, targets, context_->physicalDevice());
    return renderFrame(config, map, chosen, [&](const Frame& frame) {
      frames_.renderToTargets(frame.plan, frame.drawn, frame.map, multiview_, targets,
                              frame.progress);
    });
  }

 private:
  VulkanBackend(const VulkanOptions& options, std::unique_ptr<vulkan::VulkanContext> context)
      : options_((checkOptions(options), options)),
        context_(std::move(context)),
        pipelines_(*context_),
        frames_(*context_, pipelines_, options.timePrepassPasses),
        multiview_(options.stereoPasses == StereoPasses::Multiview ||
                   (options.stereoPasses == StereoPasses::Auto &&
                    vulkan::multiviewKeepsClippedPrimitivesInTheirView(*context_, pipelines_,
                                                                       frames_))) {}

  struct Frame {
    const vulkan::FramePlan& plan;
    const vulkan::GpuScene& drawn;
    const RetargetMap* map;  // null in plain mode
    Progress& progress;
  };

  // Plans the frame, has `draw` render it, and returns its stats.
  FrameStats renderFrame(const DisplayConfig& config, const RetargetMap* map,
                         const RenderSettings& settings,
                         const std::function<void(const Frame&)>& draw) {
    if (!scene_) throw Error(ErrorCode::InvalidInput, "Vulkan backend: render before setScene");
    const auto start = SteadyClock::now();
    const vulkan::TessellationOptions tessellation{options_.tessellationErrorPixels,
                                                   options_.maxSegmentDegrees, options_.tessellate,
                                                   options_.splitAlongCut, options_.reusePrepass,
                                                   options_.snapCutToRim,
                                                   options_.dropOutsideSourceField,
                                                   options_.drawTornPiecesUpToTheCut,
                                                   options_.warpOncePerFrame,
                                                   options_.capturedViewShiftForTests,
                                                   options_.splitCapturedTornPiecesForTests,
                                                   options_.cullFlatListPerWall.value_or(
                                                       context_->capabilities().kind !=
                                                       vulkan::DeviceKind::Cpu),
                                                   options_.cullFlatListAgainstNextWallForTests};
    const vulkan::FramePlan plan =
        vulkan::planFrame(config, map, settings, tessellation,
                          context_->capabilities().maxMultiviewViewCount);
    const bool conformal = settings.mode == RenderMode::Conformal;
    Progress progress("vulkan " + std::string(conformal ? "conformal" : "plain"),
                      plan.walls.size(), settings.showProgress);
    const bool onePass = multiview_ || plan.eyes.size() == 1;
    const vulkan::GpuScene& drawn = conformal ? sceneForWarp(config, *map, settings) : *scene_;
    draw(Frame{plan, drawn, conformal ? map : nullptr, progress});
    progress.finish();
    const double seconds = secondsSince(start);
    FrameStats stats;
    stats.backend = "vulkan";
    stats.seconds = seconds;
    stats.sceneTriangles = scene_->triangleCount();
    VulkanFrameStats& gpu = stats.vulkan.emplace();
    gpu.device = context_->capabilities().name;
    gpu.conformal = conformal;
    gpu.walls = plan.walls.size();
    gpu.viewsPerPass = onePass ? static_cast<int>(plan.eyes.size()) : 1;
    gpu.multiview = multiview_;
    gpu.gpuSeconds = frames_.gpuSeconds();
    if (conformal) {
      const auto counts = frames_.prepassCounts(drawn);
      VulkanConformalStats& prepass = gpu.conformalPrepass.emplace();
      prepass.tessellationErrorPixels = options_.tessellationErrorPixels;
      prepass.tessellation = options_.tessellate;
      prepass.trianglesSplitBeforeWarp = split_ ? split_->trianglesSplit : 0;
      prepass.trianglesDrawnFlat = counts.flat;
      prepass.trianglesTessellated = counts.tessellated + counts.dropping;
      prepass.trianglesThroughGeometryShader = counts.dropping;
      prepass.trianglesSplitAlongCut = counts.splitAlongCut;
      prepass.prepassSeconds = counts.seconds;
      prepass.prepassGpuSeconds = counts.gpuSeconds;
      prepass.prepassReused = counts.reused;
      prepass.flatTrianglesPerWall = counts.flatPerWall;
      for (std::size_t i = 0; i < counts.passGpuSeconds.size(); ++i)
        prepass.passGpuSeconds[vulkan::ConformalPrepass::kPassNames[i]] = counts.passGpuSeconds[i];
    }
    return stats;
  }

  // Triangles wider than this seen from the warp's centre are split before the warp; a split
  // made for one centre serves the next frames while none of its pieces is (hysteresis: the
  // pieces are made half as wide).
  static constexpr double kWidestTriangleDegrees = 16.0;

  // The scene as the conformal pre-pass takes it: the uploaded scene, or (where some triangle
  // spans too wide an angle seen from the warp's centre) its split (wide_triangle_split.hpp).
  const vulkan::GpuScene& sceneForWarp(const DisplayConfig& config, const RetargetMap& map,
                                       const RenderSettings& settings) {
    const glm::dvec3 c(map.reference.x, map.reference.y, map.reference.z);
    const glm::dvec3 centre =
        settings.camera.position + settings.camera.rotation() * (c - config.reference);
    // Frames from the same centre (a tracked head without navigation) decide as the last one
    // did, without the pass over every triangle.
    if (checkedCentre_ == centre) return split_ ? *split_->gpu : *scene_;
    checkedCentre_ = centre;
    if (!options_.splitWideTriangles ||
        !vulkan::hasWideTriangles(source_, centre, kWidestTriangleDegrees)) {
      split_.reset();
      return *scene_;
    }
    if (split_ && !vulkan::hasWideTriangles(split_->scene, centre, kWidestTriangleDegrees))
      return *split_->gpu;
    split_.reset();  // free the old buffers first
    vulkan::WideTriangleSplit split =
        vulkan::splitWideTriangles(source_, centre, 0.5 * kWidestTriangleDegrees);
    split_.emplace();
    split_->scene = std::move(split.scene);
    split_->trianglesSplit = split.trianglesSplit;
    split_->gpu.emplace(*context_, pipelines_, split_->scene);
    return *split_->gpu;
  }

  VulkanOptions options_;
  std::unique_ptr<vulkan::VulkanContext> context_;
  vulkan::Pipelines pipelines_;
  vulkan::FrameRenderer frames_;
  bool multiview_;  // every eye of a wall in one pass
  std::optional<vulkan::GpuScene> scene_;
  Scene source_;                     // the scene as given, for splits
  std::optional<SplitScene> split_;  // the split the last conformal frame drew, if any
  std::optional<glm::dvec3> checkedCentre_;  // the warp's centre split_ was decided for
};

}  // namespace

std::vector<VulkanDeviceInfo> listVulkanDevices() {
  const VkInstance instance = vulkan::createPlainInstance();
  std::vector<DeviceCapabilities> devices;
  try {
    devices = vulkan::queryDevices(instance);
  } catch (...) {
    vkDestroyInstance(instance, nullptr);
    throw;
  }
  vkDestroyInstance(instance, nullptr);
  std::vector<VulkanDeviceInfo> infos;
  for (std::size_t i = 0; i < devices.size(); ++i)
    infos.push_back({static_cast<int>(i), devices[i].name, vulkan::toString(devices[i].kind),
                     versionString(devices[i].apiVersion),
                     vulkan::missingRequirements(devices[i])});
  try {
    infos[vulkan::chooseDevice(devices, "")].automatic = true;
  } catch (const Error&) {
    // No device is usable: none is marked, and each lists what it lacks.
  }
  return infos;
}

std::unique_ptr<RenderBackend> makeVulkanBackend(const VulkanOptions& options) {
  return std::make_unique<VulkanBackend>(options);
}

std::unique_ptr<VulkanRenderer> makeVulkanRenderer(const VulkanOptions& options) {
  return std::make_unique<VulkanBackend>(options);
}

std::unique_ptr<VulkanRenderer> makeVulkanRendererOn(const VulkanDeviceHandles& device,
                                                     const VulkanOptions& options) {
  return std::make_unique<VulkanBackend>(options, device);
}

}  // namespace confvis
