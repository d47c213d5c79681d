// confvis view: the display live. One window per wall (placed as the config's `window` says, or
// tiled), presented every frame through a Vulkan swapchain, every wall and eye rendered through
// the conformal map that follows the tracked head (MapFollower: background re-bakes, swapped at
// frame boundaries). WASD + mouse drag navigate, C toggles conformal / plain, Esc quits. On exit
// DIR/view.json: frame times (mean, p50, p99; with and without a re-bake in flight), the frame
// log, re-bakes, tracker packets, swapchain recreations and validation messages.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "backend_factory.hpp"
#include "cluster_cli.hpp"
#include "cluster_view.hpp"
#include "command.hpp"
#include "preset_option.hpp"
#include "confvis/base/atomic_file.hpp"
#include "confvis/base/error.hpp"
#include "confvis/engine/scene_loader.hpp"
#include "confvis/runtime/background_priority.hpp"
#include "confvis/runtime/live_view.hpp"
#include "confvis/runtime/map_follower.hpp"
#include "confvis/runtime/present_context.hpp"
#include "confvis/runtime/tracker_factory.hpp"
#include "confvis/runtime/zero_extent_injection.hpp"
#include "render_options.hpp"
#include "retarget_map_source.hpp"
#include "shipped_files.hpp"

namespace confvis::cli {
namespace {

namespace fs = std::filesystem;

struct ViewArgs {
  std::string config, scene = "checker-sphere", backend = "embree", device, eyes, tracker;
  std::string mode = "conformal", stereoRays = "exact", screenshotDirectory, output, preset;
  int frames = 0, bakeResolution = 0;
  double scale = 1.0, radius = 0.10;
  bool noVsync = false, validate = false, quiet = false;
  ClusterCliOptions cluster;
};

// --eyes unset: stereo where some wall's output shows a stereo pair, mono otherwise.
bool stereoRun(const ViewArgs& args, const DisplayConfig& config) {
  if (!args.eyes.empty()) return args.eyes == "stereo";
  for (const Wall& wall : config.walls)
    if (wall.output.stereo && *wall.output.stereo != StereoOutput::Mono) return true;
  return false;
}

int runView(const ViewArgs& args) {
  const fs::path configPath = args.config.empty()
                                  ? shippedFile("configs/cave5.json", "display config")
                                  : fs::path(args.config);
  const DisplayConfig config = loadDisplayConfig(configPath);
  // Test seam: a window whose surface reports 0 x 0 for some frames (zero_extent_injection.hpp).
  if (const char* injected = std::getenv(kZeroExtentVariable); injected && *injected) {
    ZeroExtentInjection injection = parseZeroExtentInjection(injected);
    try {
      (void)config.wall(injection.wall);
    } catch (const Error& error) {
      throw Error(error.code(), std::string(kZeroExtentVariable) + ": " + error.what());
    }
    setZeroExtentInjection(std::move(injection));
  }
  // --cluster: rank 0 tracks, navigates and bakes; every rank shows its walls (cluster_view.hpp).
  std::optional<CliCluster> cluster;
  if (args.cluster.enabled) cluster.emplace(config, args.cluster);
  const bool root = !cluster || cluster->isRoot();
  std::unique_ptr<Tracker> tracker;
  if (!args.tracker.empty() && root) tracker = openTracker(args.tracker, config);
  const Scene scene = sceneByNameOrFile(args.scene);
  // Made on the presenting device: the Vulkan backend's frames then stay on the GPU.
  const LiveBackendFactory makeRenderer = [&](const PresentContext& context) {
    std::unique_ptr<RenderBackend> backend =
        makeBackendOn(context.handles(), args.backend, {args.device, {}});
    backend->setScene(scene);
    return backend;
  };

  // The first map as `confvis render` gets it (identity, or the bake cache), unless
  // --bake-resolution asks for every map at another resolution; re-bakes around the moving head
  // skip the cache.
  // Re-bakes at a low priority, so the frames keep their cores while one runs; the first map is
  // made here, at the caller's priority.
  const BakePreset preset = parseBakePreset(args.preset);
  const BakeFunction bake = followerBake(args.bakeResolution, 0.0, preset);
  const MapFollowerOptions followerOptions{.radius = args.radius};
  std::string mapOrigin = "baked now at " + std::to_string(args.bakeResolution) + " texels";
  std::optional<MapFollower> follower;
  if (root) {
    std::optional<RetargetMap> firstMap;
    if (args.bakeResolution > 0) {
      firstMap = bake(config, config.reference);
    } else {
      MapSource first = retargetMapFor(config, "", !args.quiet, preset);
      mapOrigin = first.origin;
      firstMap = std::move(first.map);
    }
    follower.emplace(config, std::move(*firstMap), inBackground(bake), followerOptions);
  }

  LiveViewOptions options;
  options.stereo = stereoRun(args, config);
  options.stereoRays = args.stereoRays == "fast" ? StereoRays::Fast : StereoRays::Exact;
  options.vsync = !args.noVsync;
  options.frames = args.frames;
  options.scale = args.scale;
  options.mode = args.mode == "plain" ? RenderMode::Plain : RenderMode::Conformal;
  options.camera.position = config.reference;
  options.screenshotDirectory = args.screenshotDirectory;
  options.validation = args.validate;
  options.showProgress = !args.quiet;
  options.renderOnPresentingDevice = args.backend == "vulkan";
  options.renderDevice = args.device;
  const fs::path output = args.output.empty() ? fs::path("out") / ("view-" + config.name)
                                              : fs::path(args.output);
  nlohmann::json report;
  if (cluster) {
    ClusterViewResult run = runClusterView(*cluster, config, makeRenderer,
                                           follower ? &*follower : nullptr, tracker.get(), options);
    // Every rank's frame states, to show they all showed the same frames.
    const nlohmann::json log = {
        {"rank", cluster->rank()}, {"walls", cluster->walls()}, {"frames", run.frames}};
    const std::string rank = std::to_string(cluster->rank());
    writeTextAtomically(output / ("cluster-rank-" + rank + ".json"), log.dump(2) + "\n");
    report = std::move(run.report);
    if (!root) {  // its own windows, frame times and validation counts; rank 0 writes view.json
      writeTextAtomically(output / ("view-rank-" + rank + ".json"), report.dump(2) + "\n");
      return 0;
    }
  } else {
    report = runLiveView(config, makeRenderer, *follower, tracker.get(), options);
  }

  report["display"] = {{"name", config.name}, {"config", configPath.string()}};
  report["scene"] = args.scene;
  report["eyes"] = options.stereo ? "stereo" : "mono";
  report["stereo_rays"] = args.stereoRays;
  report["scale"] = args.scale;
  report["vsync"] = options.vsync;
  report["map"] = mapOrigin;
  report["tracker"]["spec"] = args.tracker;
  writeTextAtomically(output / "view.json", report.dump(2) + "\n");
  const nlohmann::json& time = report["frame_time"];
  std::printf("%s: %d frames (%s), %.1f ms mean, %.1f ms p99; re-bakes %d started, %d swapped; "
              "ended by %s -> %s\n",
              config.name.c_str(), report["frame_count"].get<int>(), report["eyes"].get<std::string>().c_str(),
              time["mean_ms"].get<double>(), time["p99_ms"].get<double>(),
              report["rebakes"]["started"].get<int>(), report["rebakes"]["swapped"].get<int>(),
              report["end"].get<std::string>().c_str(), (output / "view.json").string().c_str());
  return 0;
}

const RegisterCommand registration{Command{
    "view",
    "Show a scene live on a display's walls: a window per wall, the map following the tracked "
    "head",
    [](CLI::App& sub) {
      auto args = std::make_shared<ViewArgs>();
      addDisplayConfigArgument(sub, args->config);
      addSceneOption(sub, args->scene);
      addBackendOption(sub, args->backend);
      sub.add_option("--device", args->device,
                     "Vulkan renderer's device: auto, an index or part of a name");
      sub.add_option("--eyes", args->eyes,
                     "mono or stereo; default: stereo where a wall's stereo_output shows a pair")
          ->check(CLI::IsMember({"mono", "stereo"}));
      sub.add_option("--stereo-rays", args->stereoRays,
                     "Conformal stereo eyes: exact curved rays or fast straight rays (Embree)")
          ->check(CLI::IsMember({"exact", "fast"}))
          ->capture_default_str();
      sub.add_option("--mode", args->mode, "Start conformal or plain (C toggles)")
          ->check(CLI::IsMember({"conformal", "plain"}))
          ->capture_default_str();
      sub.add_option("--tracker", args->tracker,
                     "Head tracker: path:FILE.csv (recorded, looping), dtrack:PORT, udp:PORT; "
                     "default: the head stays at the display's reference point");
      sub.add_option("--frames", args->frames, "End after N frames; default: until Esc or a "
                                               "window is closed")
          ->check(CLI::Range(1, 100000000));
      sub.add_option("--screenshot-dir", args->screenshotDirectory,
                     "Write each window's last presented frame (read back from its swapchain "
                     "image) as DIR/WALL.png");
      sub.add_flag("--no-vsync", args->noVsync,
                   "Present with MAILBOX or IMMEDIATE where the surface offers them, not FIFO");
      sub.add_option("--scale", args->scale, "Rendered pixels per wall pixel")
          ->check(kPositiveNumber)
          ->capture_default_str();
      addRebakeRadiusOption(sub, args->radius);
      addPresetOption(sub, args->preset, kLiveBakePreset);
      sub.add_option("--bake-resolution", args->bakeResolution,
                     "Cube texels per face of every map, baked without the cache; default: the config's "
                     "(first map through the cache)")
          ->check(CLI::Range(8, 4096));
      sub.add_flag("--validate", args->validate,
                   "Khronos validation on the presenting device; messages counted in view.json");
      sub.add_option("-o,--output", args->output, "Directory of view.json (default: out/view-NAME)");
      sub.add_flag("-q,--quiet", args->quiet, "No progress lines");
      addClusterOptions(sub, args->cluster);
      return [args] { return runView(*args); };
    }}};

}  // namespace
}  // namespace confvis::cli
