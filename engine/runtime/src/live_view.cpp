#include "confvis/runtime/live_view.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "confvis/base/error.hpp"
#include "confvis/backends/edge_blend_output.hpp"
#include "confvis/backends/render_plan.hpp"
#include "confvis/backends/vulkan/external_device.hpp"
#include "confvis/base/png_io.hpp"
#include "confvis/runtime/camera_controls.hpp"
#include "confvis/runtime/display_window.hpp"
#include "confvis/runtime/frame_log.hpp"
#include "confvis/runtime/present_context.hpp"
#include "confvis/runtime/window_content.hpp"
#include "confvis/runtime/window_plan.hpp"
#include "confvis/runtime/window_presenter.hpp"

namespace confvis {

namespace {

using Clock = std::chrono::steady_clock;

double secondsBetween(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}

// Walls rendered with the same eyes share one renderInto call.
struct RenderGroup {
  std::vector<Eye> eyes;
  std::vector<std::string> walls;
  RenderResult result;
};

std::vector<RenderGroup> groupByEyes(const std::vector<WindowPlan>& plans) {
  std::vector<RenderGroup> groups;
  for (const WindowPlan& plan : plans) {
    std::vector<Eye> eyes = plan.eyes;
    std::sort(eyes.begin(), eyes.end());
    auto group = std::find_if(groups.begin(), groups.end(),
                              [&](const RenderGroup& g) { return g.eyes == eyes; });
    if (group == groups.end()) group = groups.insert(groups.end(), RenderGroup{eyes, {}, {}});
    group->walls.push_back(plan.wall);
  }
  return groups;
}

// A wall name as a file name inside the screenshot directory: nothing but [A-Za-z0-9._-].
std::string fileStem(const std::string& wall) {
  std::string stem = wall;
  for (char& c : stem)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = '_';
  if (stem.empty() || stem[0] == '.') stem = "_" + stem;
  return stem;
}

void writeScreenshot(const std::filesystem::path& path, const Screenshot& shot) {
  ImageRGBA image(shot.width, shot.height);
  for (std::size_t i = 0; i < shot.rgba.size(); ++i) image.pixels[i] = shot.rgba[i] / 255.0f;
  writePng(path, image, PngOptions{.srgb = false});  // the codes as they are
}

const char* presentModeName(VkPresentModeKHR mode) {
  switch (mode) {
    case VK_PRESENT_MODE_FIFO_KHR: return "fifo";
    case VK_PRESENT_MODE_MAILBOX_KHR: return "mailbox";
    case VK_PRESENT_MODE_IMMEDIATE_KHR: return "immediate";
    case VK_PRESENT_MODE_FIFO_RELAXED_KHR: return "fifo-relaxed";
    default: return "other";
  }
}

std::string trackerText(const Tracker* tracker) {
  if (!tracker) return "no tracker";
  const TrackerStatus s = tracker->status();
  std::string text = "tracker " + std::to_string(s.packetsReceived) + " poses, " +
                     std::to_string(s.packetsDropped) + " dropped";
  if (s.lost) text += ", LOST (last pose kept)";
  return text;
}

// An eye's region of the window's content, scaled to the swapchain image it is written into.
VkRect2D scaledRegion(const EyeRegion& region, const WindowPlan& plan, VkExtent2D extent) {
  const auto scale = [](int at, int content, std::uint32_t size) {
    return static_cast<std::int32_t>(std::lround(double(at) * size / content));
  };
  const std::int32_t x0 = scale(region.x, plan.contentWidth, extent.width),
                     x1 = scale(region.x + region.width, plan.contentWidth, extent.width),
                     y0 = scale(region.y, plan.contentHeight, extent.height),
                     y1 = scale(region.y + region.height, plan.contentHeight, extent.height);
  return {{x0, y0},
          {static_cast<std::uint32_t>(std::max(1, x1 - x0)),
           static_cast<std::uint32_t>(std::max(1, y1 - y0))}};
}

PresentContextOptions presentOptions(const LiveViewOptions& options) {
  return {.validation = options.validation,
          .forRendering = options.renderOnPresentingDevice,
          .device = options.renderDevice};
}

// The walls this process shows (options.walls), in config order.
DisplayConfig shownWalls(const DisplayConfig& config, const LiveViewOptions& options) {
  DisplayConfig shown = config;
  if (options.walls)
    std::erase_if(shown.walls, [&](const Wall& wall) {
      return std::find(options.walls->begin(), options.walls->end(), wall.name) ==
             options.walls->end();
    });
  return shown;
}

// `context` and `backend` are null on a process that shows no wall (a cluster's head node).
nlohmann::json runLoop(GlfwSession& glfw, PresentContext* context, const DisplayConfig& config,
                       RenderBackend* backend, MapFollower* follower, Tracker* tracker,
                       const LiveViewOptions& options, FrameSync& sync) {
  const bool decides = sync.decides();
  if (decides && !follower)
    throw Error(ErrorCode::Internal, "view: the process that decides the frames needs a follower");
  const std::vector<WindowPlan> plans =
      context ? planWindows(shownWalls(config, options), options.stereo, options.scale,
                            glfw.monitors())
              : std::vector<WindowPlan>{};
  // Overlapping projector walls are ramped as `confvis render` ramps them (on the CPU).
  const EdgeBlender blender(config);
  // The Vulkan backend on this device writes the swapchain images itself (sRGB ones, so that
  // the blit encodes its linear values as the CPU composition would). Edge-blended walls take
  // the staging path: the blend is applied to the read-back images.
  auto* gpu = dynamic_cast<VulkanRenderer*>(backend);
  bool gpuFrames = gpu && context && gpu->deviceHandles().device == context->device() &&
                   !blender.active();
  std::vector<std::unique_ptr<DisplayWindow>> windows;
  std::vector<std::unique_ptr<WindowPresenter>> presenters;
  for (const WindowPlan& plan : plans) {
    windows.push_back(
        std::make_unique<DisplayWindow>(plan, options.windowTitle + ": " + plan.wall));
    presenters.push_back(std::make_unique<WindowPresenter>(*context, windows.back()->handle(),
                                                           options.vsync, gpuFrames));
  }
  for (const auto& presenter : presenters) gpuFrames = gpuFrames && presenter->srgb();
  std::vector<Eye> allEyes;
  if (gpuFrames)
    for (const WindowPlan& plan : plans)
      for (Eye eye : plan.eyes)
        if (std::find(allEyes.begin(), allEyes.end(), eye) == allEyes.end()) allEyes.push_back(eye);
  std::sort(allEyes.begin(), allEyes.end());
  std::vector<RenderGroup> groups = groupByEyes(plans);
  const bool capture = !options.screenshotDirectory.empty();
  sync.windowsOpen();

  RenderSettings settings;
  settings.resolutionScale = options.scale;
  settings.stereoRays = options.stereoRays;
  RenderMode mode = options.mode;
  VirtualCamera navigation = options.camera;
  CameraControls controls;
  DisplayConfig frameConfig = config;
  bool haveFrameConfig = false;
  std::uint64_t frameConfigGeneration = 0;
  int bakesStartedBefore = decides ? follower->stats().bakesStarted : 0;
  FrameLog log;
  nlohmann::json bakeErrors = nlohmann::json::array();
  std::string endReason = "frames";

  const Clock::time_point start = Clock::now();
  Clock::time_point frameStart = start, lastTitle = start - std::chrono::seconds(1),
                    lastProgress = start;
  double lastFrameSeconds = 0.0;
  for (int index = 0;; ++index) {
    glfw.pollEvents();
    bool quit = false, closed = false;
    for (const auto& window : windows) {
      const WindowInput input = window->takeInput();
      if (input.toggleMode)
        mode = mode == RenderMode::Conformal ? RenderMode::Plain : RenderMode::Conformal;
      quit = quit || input.quit;
      closed = closed || window->closeRequested();
    }
    LiveFrameState state;
    FollowerFrame frame;
    FrameRecord record;
    if (decides) {  // elsewhere keys and mouse steer nothing: the decision arrives below
      controls.update(windows, navigation, lastFrameSeconds);
      HeadPose head{config.reference};
      if (tracker)
        if (const std::optional<TrackedPose> pose = tracker->latest()) head = pose->head;
      frame = follower->beginFrame(head);
      state.frame = static_cast<std::uint64_t>(index);
      state.seconds = secondsBetween(start, Clock::now());
      state.head = head;
      state.camera = navigation;
      state.conformal = mode == RenderMode::Conformal;
      state.stop = quit || closed;
      state.quit = state.stop || (options.frames > 0 && index + 1 >= options.frames);
      if (state.stop) endReason = closed ? "window closed" : "escape";
      record.bakeStarted = follower->stats().bakesStarted > bakesStartedBefore;
      record.bakeInFlight = frame.baking;
      bakesStartedBefore = follower->stats().bakesStarted;
    }
    const SyncedMap synced = sync.exchange(state, decides ? &frame : nullptr);
    if (state.stop) {
      if (!decides) endReason = "ended by the deciding process";
      break;
    }
    const glm::dvec3 reference(synced.map->reference.x, synced.map->reference.y,
                               synced.map->reference.z);
    if (!haveFrameConfig || state.mapGeneration != frameConfigGeneration) {
      frameConfig = withReference(config, reference);  // render_plan wants the map's reference
      frameConfigGeneration = state.mapGeneration;
      haveFrameConfig = true;
    }
    record.mapGeneration = state.mapGeneration;
    record.mapSwapped = synced.swapped;
    record.conformal = state.conformal;
    record.head = {state.head.position.x, state.head.position.y, state.head.position.z};

    // The virtual world stays put when the map's reference moves: the camera follows it.
    settings.mode = state.conformal ? RenderMode::Conformal : RenderMode::Plain;
    settings.head = state.head;
    settings.camera = state.camera;
    settings.camera.position =
        state.camera.position + state.camera.rotation() * (reference - config.reference);
    const Clock::time_point renderStart = Clock::now();
    Clock::time_point presentStart;
    const auto frameError = [&](const Error& error) {
      return Error(error.code(), "frame " + std::to_string(index) + ": " + error.what());
    };
    if (gpuFrames) {
      // Every window's swapchain image, every eye blitted into its region, one submission chain.
      std::vector<VulkanImageTarget> targets;
      std::vector<std::size_t> acquired;
      for (std::size_t w = 0; w < windows.size(); ++w) {
        const std::optional<WindowPresenter::Acquired> image = presenters[w]->acquire();
        if (!image) continue;  // minimised or out of date: this window skips the frame
        acquired.push_back(w);
        for (const EyeRegion& region : plans[w].regions)
          targets.push_back({plans[w].wall, region.eye, image->image, image->format,
                             image->extent, 0, scaledRegion(region, plans[w], image->extent),
                             VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                             image->acquired, image->written});
      }
      settings.eyes = allEyes;
      settings.walls.clear();
      try {
        if (!targets.empty())
          gpu->renderImages(frameConfig, synced.map.get(), settings, targets);
      } catch (const Error& error) {
        throw frameError(error);
      }
      presentStart = Clock::now();
      sync.beforePresent(secondsBetween(renderStart, presentStart));
      for (std::size_t w : acquired) presenters[w]->presentAcquired(capture);
      record.windowsPresented = static_cast<int>(acquired.size());
    } else {
      for (RenderGroup& group : groups) {
        settings.eyes = group.eyes;
        settings.walls = group.walls;
        try {
          backend->renderInto(frameConfig, synced.map.get(), settings, group.result);
        } catch (const Error& error) {
          throw frameError(error);
        }
        blender.apply(group.result.images);
      }
      presentStart = Clock::now();
      for (std::size_t w = 0; w < windows.size(); ++w) {
        const WindowPlan& plan = plans[w];
        auto imageOf = [&](Eye eye) -> const ImageRGBA* {
          for (const RenderGroup& group : groups)
            for (const WallImage& image : group.result.images)
              if (image.wall == plan.wall && image.eye == eye) return &image.image;
          return nullptr;
        };
        composeWindow(plan, imageOf, presenters[w]->beginFrame(plan.contentWidth, plan.contentHeight));
      }
      sync.beforePresent(secondsBetween(renderStart, presentStart));
      for (const auto& presenter : presenters)
        record.windowsPresented += presenter->present(capture) ? 1 : 0;
    }
    if (decides)
      for (const std::string& message : follower->takeErrors()) {
        bakeErrors.push_back({{"frame", index}, {"message", message}});
        std::fprintf(stderr, "view: frame %d: re-bake failed, keeping the old map: %s\n", index,
                     message.c_str());
      }
    const Clock::time_point frameEnd = Clock::now();
    record.renderSeconds = secondsBetween(renderStart, presentStart);
    record.presentSeconds = secondsBetween(presentStart, frameEnd);
    record.frameSeconds = lastFrameSeconds = secondsBetween(frameStart, frameEnd);
    frameStart = frameEnd;
    log.add(record);

    if (secondsBetween(lastTitle, frameEnd) >= 0.25) {  // titles are cheap but not free
      lastTitle = frameEnd;
      char status[160];
      std::snprintf(status, sizeof status, " | %.1f ms | %s | map %llu%s | ",
                    record.frameSeconds * 1e3, state.conformal ? "conformal" : "plain",
                    static_cast<unsigned long long>(state.mapGeneration),
                    frame.baking ? " (re-baking)" : "");
      for (const auto& window : windows)
        window->setTitle(options.windowTitle + ": " + window->plan().wall + status +
                         trackerText(tracker));
    }
    if (decides && options.showProgress && secondsBetween(lastProgress, frameEnd) >= 1.0) {
      lastProgress = frameEnd;
      std::fprintf(stderr, "view: frame %d, %.1f ms, map %llu%s, %s\n", index + 1,
                   record.frameSeconds * 1e3,
                   static_cast<unsigned long long>(state.mapGeneration),
                   frame.baking ? " (re-baking)" : "", trackerText(tracker).c_str());
    }
    if (state.quit) break;
  }

  nlohmann::json windowReport = nlohmann::json::array();
  // A directory that cannot be made shows as the first screenshot's write error naming the file.
  std::error_code uncreatable;
  if (capture) std::filesystem::create_directories(options.screenshotDirectory, uncreatable);
  for (std::size_t w = 0; w < windows.size(); ++w) {
    presenters[w]->finish();
    const WindowPlan& plan = plans[w];
    nlohmann::json entry = {
        {"wall", plan.wall},
        {"stereo_output", toString(plan.stereo)},
        {"content", {plan.contentWidth, plan.contentHeight}},
        {"swapchain", {presenters[w]->extent().width, presenters[w]->extent().height}},
        {"present_mode", presentModeName(presenters[w]->presentMode())},
        {"swapchain_recreations", presenters[w]->recreations()}};
    const Screenshot& shot = presenters[w]->latestScreenshot();
    if (capture && !shot.rgba.empty()) {
      const std::string file = fileStem(plan.wall) + ".png";
      writeScreenshot(options.screenshotDirectory / file, shot);
      entry["screenshot"] = file;
    }
    windowReport.push_back(entry);
  }

  const ValidationReport validation = context ? context->validation() : ValidationReport{};
  nlohmann::json report = log.toJson();
  report["frame_count"] = log.records().size();
  report["end"] = endReason;
  report["seconds"] = secondsBetween(start, Clock::now());
  report["present_device"] = context ? context->deviceName() : "none";
  report["backend"] = backend ? backend->name() : "none";
  // How frames reach the windows: "gpu" (rendered on the presenting device, blitted into the
  // swapchain images) or "staging" (read back, composed on the CPU, uploaded and blitted).
  report["frame_path"] = gpuFrames ? "gpu" : "staging";
  report["edge_blend"] = blender.active();
  report["windows"] = windowReport;
  if (decides) {
    const MapFollowerStats stats = follower->stats();
    report["rebakes"] = {{"started", stats.bakesStarted},
                         {"swapped", stats.bakesSucceeded},
                         {"failed", stats.bakesFailed},
                         {"running_at_end",
                          stats.bakesStarted - stats.bakesSucceeded - stats.bakesFailed},
                         {"errors", bakeErrors}};
    const TrackerStatus trackerStatus = tracker ? tracker->status() : TrackerStatus{};
    report["tracker"] = {{"packets_received", trackerStatus.packetsReceived},
                         {"packets_dropped", trackerStatus.packetsDropped},
                         {"lost", trackerStatus.lost},
                         {"present", tracker != nullptr}};
  }
  report["validation"] = {{"enabled", validation.enabled},
                          {"errors", validation.errors},
                          {"warnings", validation.warnings},
                          {"messages", validation.messages}};
  return report;
}

}  // namespace

nlohmann::json runLiveView(const DisplayConfig& config, const LiveBackendFactory& makeBackend,
                           MapFollower* follower, Tracker* tracker,
                           const LiveViewOptions& options, FrameSync& sync) {
  GlfwSession glfw;
  if (options.walls && options.walls->empty())  // shows nothing: no device, no renderer
    return runLoop(glfw, nullptr, config, nullptr, follower, tracker, options, sync);
  PresentContext context(presentOptions(options));
  const std::unique_ptr<RenderBackend> backend = makeBackend(context);  // gone before context
  return runLoop(glfw, &context, config, backend.get(), follower, tracker, options, sync);
}

nlohmann::json runLiveView(const DisplayConfig& config, const LiveBackendFactory& makeBackend,
                           MapFollower& follower, Tracker* tracker,
                           const LiveViewOptions& options) {
  LocalFrameSync local;
  return runLiveView(config, makeBackend, &follower, tracker, options, local);
}

nlohmann::json runLiveView(const DisplayConfig& config, RenderBackend& backend,
                           MapFollower& follower, Tracker* tracker,
                           const LiveViewOptions& options) {
  GlfwSession glfw;
  PresentContext context(presentOptions(options));
  LocalFrameSync local;
  return runLoop(glfw, &context, config, &backend, &follower, tracker, options, local);
}

}  // namespace confvis
