#include "cluster_view.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <vector>

#include "confvis/base/error.hpp"
#ifdef CONFVIS_HAVE_CLUSTER
#include "confvis/runtime/camera_controls.hpp"
#include "confvis/runtime/cluster.hpp"
#include "confvis/runtime/display_window.hpp"
#include "confvis/runtime/frame_log.hpp"
#include "confvis/runtime/present_context.hpp"
#include "confvis/runtime/window_content.hpp"
#include "confvis/runtime/window_plan.hpp"
#include "confvis/runtime/window_presenter.hpp"
#endif

namespace confvis::cli {

#ifdef CONFVIS_HAVE_CLUSTER

namespace {

using Clock = std::chrono::steady_clock;

// How long the other ranks wait for rank 0's first frame (it may still be baking the map).
constexpr double kFirstFrameSeconds = 600.0;

double secondsBetween(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}

// What rank 0 decides each frame: the cluster's frame state and whether the map is applied.
struct ViewFrameState : ClusterFrameState {
  bool conformal = true;
};

nlohmann::json stateJson(const ViewFrameState& s) {
  auto vec = [](const glm::dvec3& v) { return nlohmann::json{v.x, v.y, v.z}; };
  return {{"frame", s.frame},
          {"seconds", s.seconds},
          {"head", {{"position", vec(s.head.position)},
                    {"orientation", {s.head.orientation.w, s.head.orientation.x,
                                     s.head.orientation.y, s.head.orientation.z}}}},
          {"camera", {{"position", vec(s.camera.position)}, {"yaw", s.camera.yawDegrees},
                      {"pitch", s.camera.pitchDegrees}}},
          {"map_generation", s.mapGeneration},
          {"conformal", s.conformal},
          {"quit", s.quit}};
}

}  // namespace

ClusterViewResult runClusterView(CliCluster& cli, const DisplayConfig& config,
                                 RenderBackend& backend, MapFollower* follower, Tracker* tracker,
                                 const LiveViewOptions& options) {
  Cluster& cluster = cli.cluster();
  const bool root = cluster.isRoot();
  if (root && !follower) throw Error(ErrorCode::Internal, "view --cluster: rank 0 needs the follower");
  DisplayConfig mine = config;  // the walls this rank shows
  std::erase_if(mine.walls, [&](const Wall& w) {
    return std::find(cluster.walls().begin(), cluster.walls().end(), w.name) ==
           cluster.walls().end();
  });
  GlfwSession glfw;
  std::optional<PresentContext> context;  // a rank without walls (a head node) presents nothing
  std::vector<WindowPlan> plans;
  if (!mine.walls.empty()) {
    context.emplace(PresentContextOptions{.validation = options.validation});
    plans = planWindows(mine, options.stereo, options.scale, glfw.monitors());
  }
  std::vector<std::unique_ptr<DisplayWindow>> windows;
  std::vector<std::unique_ptr<WindowPresenter>> presenters;
  for (const WindowPlan& plan : plans) {
    windows.push_back(std::make_unique<DisplayWindow>(
        plan, "confvis view: " + plan.wall + " (rank " + std::to_string(cli.rank()) + ")"));
    presenters.push_back(
        std::make_unique<WindowPresenter>(*context, windows.back()->handle(), options.vsync));
  }
  std::vector<RenderResult> results(plans.size());
  // Every rank has its windows before rank 0 starts sending the map (opening them may take long
  // on a loaded machine, longer than the timeout the map's broadcast allows).
  cluster.swapLock(kFirstFrameSeconds);

  RenderSettings settings;
  settings.resolutionScale = options.scale;
  settings.stereoRays = options.stereoRays;
  RenderMode mode = options.mode;
  VirtualCamera navigation = options.camera;
  CameraControls controls;
  DisplayConfig frameConfig = config;
  // Plain numbers with flags, not optionals: GCC 12 warns of optional compares (maybe-uninitialized).
  bool haveFrameConfig = false, pending = false;
  std::uint64_t frameConfigGeneration = 0, sharedGeneration = 0, pendingGeneration = 0;
  int bakesStartedBefore = root ? follower->stats().bakesStarted : 0;
  FrameLog log;
  ClusterViewResult result;
  std::string endReason = "frames";

  const Clock::time_point start = Clock::now();
  Clock::time_point frameStart = start, lastProgress = start;
  double lastFrameSeconds = 0.0;
  for (std::uint64_t index = 0;; ++index) {
    glfw.pollEvents();
    bool quit = false, closed = false;
    for (const auto& window : windows) {  // only rank 0's input steers the display
      const WindowInput input = window->takeInput();
      if (root && input.toggleMode)
        mode = mode == RenderMode::Conformal ? RenderMode::Plain : RenderMode::Conformal;
      quit = quit || input.quit;
      closed = closed || window->closeRequested();
    }
    ViewFrameState state;
    FrameRecord record;
    if (root) {
      controls.update(windows, navigation, lastFrameSeconds);
      HeadPose head{config.reference};
      if (tracker)
        if (const std::optional<TrackedPose> pose = tracker->latest()) head = pose->head;
      const FollowerFrame frame = follower->beginFrame(head);
      if (index == 0) {  // every rank holds the first map before the first frame
        cluster.shareMapNow(frame.map, frame.generation);
        sharedGeneration = frame.generation;
      } else if (frame.generation != sharedGeneration &&
                 !(pending && pendingGeneration == frame.generation)) {
        cluster.shareMap(frame.map, frame.generation);  // travels while frames go on
        pending = true;
        pendingGeneration = frame.generation;
      }
      if (cluster.progressMaps() && pending) {  // reached every rank: swap it in now
        sharedGeneration = pendingGeneration;
        pending = false;
      }
      state.frame = index;
      state.seconds = secondsBetween(start, Clock::now());
      state.head = head;
      state.camera = navigation;
      state.mapGeneration = sharedGeneration;
      state.conformal = mode == RenderMode::Conformal;
      state.quit = quit || closed ||
                   (options.frames > 0 && index + 1 >= static_cast<std::uint64_t>(options.frames));
      if (quit || closed) endReason = closed ? "window closed" : "escape";
      record.bakeStarted = follower->stats().bakesStarted > bakesStartedBefore;
      record.bakeInFlight = frame.baking;
      bakesStartedBefore = follower->stats().bakesStarted;
      for (const std::string& message : follower->takeErrors())
        std::fprintf(stderr, "view: frame %llu: re-bake failed, keeping the old map: %s\n",
                     static_cast<unsigned long long>(index), message.c_str());
    } else {
      cluster.progressMaps();  // chunks of a new map arrive between frames
    }
    const std::uint64_t generationBefore = cluster.mapGeneration();
    cluster.exchangeFrame(state, index == 0 ? kFirstFrameSeconds : 0.0);
    const std::shared_ptr<const RetargetMap> map = cluster.map();
    const glm::dvec3 reference(map->reference.x, map->reference.y, map->reference.z);
    if (!haveFrameConfig || frameConfigGeneration != state.mapGeneration) {
      frameConfig = withReference(config, reference);
      frameConfigGeneration = state.mapGeneration;
      haveFrameConfig = true;
    }
    record.mapGeneration = state.mapGeneration;
    record.mapSwapped = index > 0 && cluster.mapGeneration() != generationBefore;
    record.conformal = state.conformal;

    // The virtual world stays put when the map's reference moves: the camera follows it.
    settings.mode = state.conformal ? RenderMode::Conformal : RenderMode::Plain;
    settings.head = state.head;
    settings.camera = state.camera;
    settings.camera.position =
        state.camera.position + state.camera.rotation() * (reference - config.reference);
    const Clock::time_point renderStart = Clock::now();
    for (std::size_t w = 0; w < plans.size(); ++w) {
      settings.eyes = plans[w].eyes;
      settings.walls = {plans[w].wall};
      try {
        backend.renderInto(frameConfig, map.get(), settings, results[w]);
      } catch (const Error& error) {
        throw Error(error.code(), "frame " + std::to_string(index) + ": " + error.what());
      }
    }
    for (std::size_t w = 0; w < plans.size(); ++w) {
      auto imageOf = [&](Eye eye) -> const ImageRGBA* {
        for (const WallImage& image : results[w].images)
          if (image.eye == eye) return &image.image;
        return nullptr;
      };
      composeWindow(plans[w], imageOf,
                    presenters[w]->beginFrame(plans[w].contentWidth, plans[w].contentHeight));
    }
    const Clock::time_point presentStart = Clock::now();
    // Every window shows this frame at once; slower ranks get a few times this rank's render
    // time before they count as lost.
    cluster.swapLock(4.0 * secondsBetween(renderStart, presentStart) + 1.0);
    for (const auto& presenter : presenters) presenter->present(false);
    const Clock::time_point frameEnd = Clock::now();
    record.renderSeconds = secondsBetween(renderStart, presentStart);
    record.presentSeconds = secondsBetween(presentStart, frameEnd);
    record.frameSeconds = lastFrameSeconds = secondsBetween(frameStart, frameEnd);
    frameStart = frameEnd;
    log.add(record);
    result.frames.push_back(stateJson(state));
    if (root && options.showProgress && secondsBetween(lastProgress, frameEnd) >= 1.0) {
      lastProgress = frameEnd;
      std::fprintf(stderr, "view: frame %llu, %.1f ms, map %llu, %d ranks\n",
                   static_cast<unsigned long long>(index + 1), record.frameSeconds * 1e3,
                   static_cast<unsigned long long>(state.mapGeneration), cluster.size());
    }
    if (state.quit) break;
  }
  for (const auto& presenter : presenters) presenter->finish();
  if (!root) return result;

  nlohmann::json windowReport = nlohmann::json::array();
  for (std::size_t w = 0; w < plans.size(); ++w)
    windowReport.push_back({{"wall", plans[w].wall},
                            {"stereo_output", toString(plans[w].stereo)},
                            {"content", {plans[w].contentWidth, plans[w].contentHeight}}});
  const MapFollowerStats stats = follower->stats();
  result.report = log.toJson();
  result.report["frame_count"] = log.records().size();
  result.report["end"] = endReason;
  result.report["seconds"] = secondsBetween(start, Clock::now());
  result.report["windows"] = windowReport;  // rank 0's; every rank logs its frames
  result.report["rebakes"] = {{"started", stats.bakesStarted},
                              {"swapped", stats.bakesSucceeded},
                              {"failed", stats.bakesFailed},
                              {"running_at_end",
                               stats.bakesStarted - stats.bakesSucceeded - stats.bakesFailed}};
  result.report["cluster"] = cli.report();
  return result;
}

#else

ClusterViewResult runClusterView(CliCluster&, const DisplayConfig&, RenderBackend&, MapFollower*,
                                 Tracker*, const LiveViewOptions&) {
  throw Error(ErrorCode::InvalidInput,
              "--cluster: this confvis was built without MPI (install libopenmpi-dev and "
              "rebuild with CONFVIS_CLUSTER=ON)");
}

#endif

}  // namespace confvis::cli
