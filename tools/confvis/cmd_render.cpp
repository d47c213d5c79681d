// confvis render: offline retargets of a scene to every wall of a display, as OpenEXR + PNG.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "backend_factory.hpp"
#include "cluster_cli.hpp"
#include "command.hpp"
#include "preset_option.hpp"
#include "confvis/backends/edge_blend_output.hpp"
#include "confvis/backends/render_output.hpp"
#include "confvis/backends/render_plan.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/input_limits.hpp"
#include "confvis/base/stopwatch.hpp"
#include "confvis/engine/scene_loader.hpp"
#include "render_options.hpp"
#include "retarget_map_source.hpp"
#include "scene_option.hpp"
#include "shipped_files.hpp"

namespace confvis::cli {
namespace {

namespace fs = std::filesystem;

struct RenderArgs {
  std::string config, scene = "checker-sphere", backend = "embree", mode = "conformal";
  std::string device;
  std::optional<double> tessellationErrorPixels;
  std::string eyes = "mono", stereoRays = "exact", camera, mapDirectory, output, preset;
  std::string interpolation;
  std::vector<std::string> walls;
  int spp = 1;
  double scale = 1.0, sceneScale = 1.0;
  bool ambientOcclusion = false, quiet = false;
  ClusterCliOptions cluster;
};

VirtualCamera parseCamera(const std::string& text) {
  std::vector<double> values;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? comma : comma - start);
    try {
      std::size_t used = 0;
      values.push_back(std::stod(item, &used));
      if (used != item.size()) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw Error(ErrorCode::InvalidInput,
                  "--camera expects x,y,z[,yaw,pitch] (metres, degrees), got '" + text + "'");
    }
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if ((values.size() != 3 && values.size() != 5) ||
      !std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); }))
    throw Error(ErrorCode::InvalidInput,
                "--camera expects x,y,z[,yaw,pitch] (metres, degrees), got '" + text + "'");
  VirtualCamera camera;
  camera.position = {values[0], values[1], values[2]};
  if (values.size() == 5) {
    camera.yawDegrees = values[3];
    camera.pitchDegrees = values[4];
  }
  return camera;
}

// How long the other ranks of a --cluster run wait for rank 0's bake of the map.
constexpr double kClusterBakeSeconds = 600.0;

int runRender(const RenderArgs& args) {
  const auto start = SteadyClock::now();
  const fs::path configPath = args.config.empty()
                                  ? shippedFile("configs/cave5.json", "display config")
                                  : fs::path(args.config);
  const DisplayConfig config = loadDisplayConfig(configPath);

  RenderSettings settings;
  settings.mode = args.mode == "plain" ? RenderMode::Plain : RenderMode::Conformal;
  settings.eyes = args.eyes == "stereo" ? std::vector<Eye>{Eye::Left, Eye::Right}
                                        : std::vector<Eye>{Eye::Center};
  settings.stereoRays = args.stereoRays == "fast" ? StereoRays::Fast : StereoRays::Exact;
  settings.walls = args.walls;
  settings.samplesPerPixel = args.spp;
  settings.ambientOcclusion = args.ambientOcclusion;
  settings.head.position = config.reference;  // the tracked head at its nominal position
  settings.camera.position = config.reference;
  if (!args.camera.empty()) settings.camera = parseCamera(args.camera);
  settings.resolutionScale = args.scale;
  settings.showProgress = !args.quiet;

  std::unique_ptr<RenderBackend> backend = makeBackend(args.backend, {args.device, args.tessellationErrorPixels});
  std::optional<CliCluster> cluster;  // --cluster: this rank renders its walls, rank 0 writes
  if (args.cluster.enabled) cluster.emplace(config, args.cluster);
  std::optional<MapSource> map;  // one bake for all: rank 0's, shared with the others
  if (settings.mode == RenderMode::Conformal && (!cluster || cluster->isRoot()))
    map = retargetMapFor(config, args.mapDirectory, !args.quiet, parseBakePreset(args.preset),
                         interpolationOverride(args.interpolation));
  const RetargetMap* renderMap = map ? &map->map : nullptr;
  if (cluster) renderMap = cluster->shareMap(renderMap, kClusterBakeSeconds);
  // Check walls, eyes and map before the (possibly slow) scene load.
  planRender(config, renderMap, settings);
  const double setupSeconds = secondsSince(start);

  auto stage = SteadyClock::now();
  const Scene scene = loadSceneInUnits(args.scene, args.sceneScale, config);
  const double loadSeconds = secondsSince(stage);
  stage = SteadyClock::now();
  backend->setScene(scene);
  const double uploadSeconds = secondsSince(stage);
  stage = SteadyClock::now();
  std::optional<RenderResult> rendered =
      cluster ? cluster->render(*backend, config, renderMap, settings)
              : backend->render(config, renderMap, settings);
  if (!rendered) return 0;  // a cluster rank other than 0: rank 0 writes every image
  EdgeBlender(config).apply(rendered->images);  // overlapping projectors, when configured
  const RenderResult& result = *rendered;
  const double renderSeconds = secondsSince(stage);

  const fs::path output = args.output.empty()
                              ? childPath("out", "render-" + config.name, "display name")
                              : fs::path(args.output);
  nlohmann::json extra = {
      {"display", {{"config", configPath.string()}}},
      {"scene", {{"source", args.scene},
                 {"name", scene.name},
                 {"triangles", scene.triangleCount()},
                 {"vertices", scene.vertexCount()}}},
      {"map", map ? nlohmann::json(map->origin) : nlohmann::json(nullptr)},
      {"cluster", cluster ? cluster->report() : nlohmann::json(nullptr)},
      {"timings", {{"setup_seconds", setupSeconds},
                   {"scene_load_seconds", loadSeconds},
                   {"scene_upload_seconds", uploadSeconds},
                   {"render_seconds", renderSeconds},
                   {"seconds_before_writing", secondsSince(start)}}}};
  writeRenderOutput(output, config, settings, result, extra);  // adds write_seconds
  // Rays per second only where rays were traced (a rasterizer reports none).
  const double raysPerSecond = result.stats.embree ? result.stats.embree->raysPerSecond : 0.0;
  char rate[48] = "";
  if (raysPerSecond > 0) std::snprintf(rate, sizeof rate, ", %.1f Mrays/s", raysPerSecond * 1e-6);
  // The device's own time where it was measured (Vulkan: timestamps; readback excluded).
  if (const double gpu = result.stats.vulkan ? result.stats.vulkan->gpuSeconds.value_or(0.0) : 0.0;
      gpu > 0)
    std::snprintf(rate, sizeof rate, ", %.1f ms on the device", gpu * 1e3);
  std::printf("%s: %zu images (%s, %s) of '%s' in %.2f s%s -> %s\n", config.name.c_str(),
              result.images.size(), modeName(settings.mode), args.eyes.c_str(),
              scene.name.c_str(), renderSeconds, rate, output.string().c_str());
  return 0;
}

const RegisterCommand registration{Command{
    "render", "Render a scene to every wall of a display (OpenEXR + PNG previews)",
    [](CLI::App& sub) {
      auto args = std::make_shared<RenderArgs>();
      sub.add_option("config", args->config,
                     "Display config (JSON); default: configs/cave5.json");
      addSceneOption(sub, args->scene);
      addBackendOption(sub, args->backend);
      sub.add_option("--device", args->device,
                     "Vulkan device: auto (discrete GPU first, then lavapipe), an index or part "
                     "of a name");
      sub.add_option("--tess-error", args->tessellationErrorPixels,
                     "Vulkan conformal: how far (pixels) a drawn edge may stray from its exact "
                     "warped curve before it is subdivided; smaller is sharper and slower "
                     "(default 0.5)")
          ->check(kPositiveNumber);
      sub.add_option("--mode", args->mode,
                     "conformal: through the display's conformal map; plain: ordinary off-axis")
          ->check(CLI::IsMember({"conformal", "plain"}))
          ->capture_default_str();
      sub.add_option("--eyes", args->eyes, "mono: the head's centre; stereo: left and right eyes")
          ->check(CLI::IsMember({"mono", "stereo"}))
          ->capture_default_str();
      sub.add_option("--stereo-rays", args->stereoRays,
                     "Conformal stereo eyes: exact curved rays or fast straight rays")
          ->check(CLI::IsMember({"exact", "fast"}))
          ->capture_default_str();
      sub.add_option("--wall", args->walls, "Render only this wall (repeatable)");
      sub.add_option("--spp", args->spp, "Samples per pixel (stratified)")
          ->check(CLI::Range(1, 4096))
          ->capture_default_str();
      sub.add_option("--camera", args->camera,
                     "Virtual camera x,y,z[,yaw,pitch]: where the display's reference point is "
                     "in the scene (metres) and how it is turned (degrees)");
      addOutputScaleOption(sub, args->scale);
      addSceneScaleOption(sub, args->sceneScale);
      addPresetOption(sub, args->preset, kOfflineBakePreset);
      addInterpolationOption(sub, args->interpolation);
      sub.add_option("--map", args->mapDirectory,
                     "Baked map directory (ray.exr, geom.exr) for conformal mode");
      sub.add_flag("--ao", args->ambientOcclusion, "Ambient occlusion");
      sub.add_option("-o,--output", args->output, "Output directory (default: out/render-NAME)");
      sub.add_flag("-q,--quiet", args->quiet, "No progress bar");
      addClusterOptions(sub, args->cluster);
      return [args] { return runRender(*args); };
    }}};

}  // namespace
}  // namespace confvis::cli
