// Vulkan backend benchmark (run by hand, never in CI): frame time of conformal rendering as a
// multiple of plain rendering of the same scene, walls and resolution, measured in the same run
// (goal <= 1.5), and how that ratio and the image move with the tessellation threshold.
// Timing maps: the identity (no bend: the warp's fixed cost), a Moebius zoom (a smooth conformal
// map), an azimuth squeeze (a cut along a half-meridian and singular poles: a stress test) and
// the config's real baked map (its cut and rim) at the default threshold. Threshold sweeps: under the zoom map against the closed form (checker colours
// along T_ray of each pixel's direction), and under the config's real baked map against the
// Embree backend's render of the centre eye (the backward path of design note §5).
// Times are medians of wall-clock, of process CPU time (lavapipe renders on the CPU in this
// process, so CPU time is the steadier measure on a shared machine) and of GPU time
// (timestamps around the pre-pass and the render passes: on a GPU the host's submissions, waits
// and readback dominate the wall clock, and a display application does not read its frames
// back). The timing table renders plain, conformal and reused-pre-pass frames in turn, round
// after round, and its ratios are medians of each round's ratio, so that a shared machine's
// drift cancels.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <optional>
#include <string>
#include <vector>

#include "confvis/backends/embree/embree_backend.hpp"
#include "confvis/backends/vulkan_backend.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/png_io.hpp"
#include "confvis/base/stopwatch.hpp"
#include "confvis/conformal/bake_display.hpp"
#include "confvis/engine/builtin_scenes.hpp"
#include "vulkan_image_checks.hpp"  // closed-form image comparison shared with the tests
#include "vulkan_test_maps.hpp"     // analytic maps shared with the tests

using namespace confvis;

namespace {

double cpuSeconds() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// The conformal pre-pass's figures of a Vulkan frame (all zero for another frame).
VulkanConformalStats prepassOf(const RenderResult& result) {
  const std::optional<VulkanFrameStats>& vulkan = result.stats.vulkan;
  return vulkan && vulkan->conformalPrepass ? *vulkan->conformalPrepass : VulkanConformalStats{};
}

std::string deviceOf(const RenderResult& result) {
  return result.stats.vulkan ? result.stats.vulkan->device : "?";
}

struct Timing {
  double seconds = 0, cpu = 0, gpu = 0;  // medians per frame (gpu: 0 without timestamps)
  std::vector<double> wall, cpuFrames, gpuFrames;  // every timed frame, in order
  // The pre-pass's passes' GPU times per frame where they were timed (--time-passes).
  std::vector<std::pair<std::string, std::vector<double>>> passFrames;
  RenderResult last;
};

// Median over the rounds of a's frame time over b's (timeInterleaved: frame i of each was timed
// in the same round), so that the machine's drift between rounds cancels; 0 without times.
double pairedRatio(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> ratios;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
    if (b[i] > 0.0) ratios.push_back(a[i] / b[i]);
  return ratios.empty() ? 0.0 : median(ratios);
}

struct TimedRun {
  RenderBackend* backend;
  const RetargetMap* map;  // nullptr: plain
};

// Times the runs one frame each in turn, round after round, so that the machine's drift (a
// shared VM's speed moves by 10-20 % within seconds) weighs on every run alike and the ratios
// between them hold even where their absolute times do not.
std::vector<Timing> timeInterleaved(const std::vector<TimedRun>& runs, const DisplayConfig& config,
                                    RenderSettings settings, int repeats) {
  const auto settingsFor = [&](const TimedRun& run) {
    settings.mode = run.map ? RenderMode::Conformal : RenderMode::Plain;
    return settings;
  };
  for (const TimedRun& run : runs) run.backend->render(config, run.map, settingsFor(run));  // warm-up
  std::vector<std::vector<double>> wall(runs.size()), cpu(runs.size()), gpu(runs.size());
  std::vector<Timing> timings(runs.size());
  for (int i = 0; i < repeats; ++i)
    for (std::size_t r = 0; r < runs.size(); ++r) {
      const RenderSettings frameSettings = settingsFor(runs[r]);
      const auto start = SteadyClock::now();
      const double cpuStart = cpuSeconds();
      timings[r].last = runs[r].backend->render(config, runs[r].map, frameSettings);
      cpu[r].push_back(cpuSeconds() - cpuStart);
      wall[r].push_back(secondsSince(start));
      // The device's own time (timestamps around the pre-pass and the render passes): on a GPU
      // the host's submissions, waits and readback dominate the wall clock.
      const std::optional<VulkanFrameStats>& vulkan = timings[r].last.stats.vulkan;
      gpu[r].push_back(vulkan ? vulkan->gpuSeconds.value_or(0.0) : 0.0);
      if (const auto passes = prepassOf(timings[r].last).passGpuSeconds; !passes.empty()) {
        auto& frames = timings[r].passFrames;
        if (frames.empty())
          for (const auto& [pass, seconds] : passes) frames.push_back({pass, {}});
        for (auto& [pass, seconds] : frames) {
          const auto found = passes.find(pass);
          seconds.push_back(found != passes.end() ? found->second : 0.0);
        }
      }
    }
  for (std::size_t r = 0; r < runs.size(); ++r) {
    timings[r].seconds = median(wall[r]);
    timings[r].cpu = median(cpu[r]);
    timings[r].gpu = median(gpu[r]);
    timings[r].wall = wall[r];
    timings[r].cpuFrames = cpu[r];
    timings[r].gpuFrames = gpu[r];
  }
  return timings;
}

// One run's frames: a warm-up, then `repeats` timed (the mode follows `map`).
Timing timeFrames(RenderBackend& backend, const DisplayConfig& config, const RetargetMap* map,
                  const RenderSettings& settings, int repeats) {
  return timeInterleaved({{&backend, map}}, config, settings, repeats).front();
}

// Fraction of the unambiguous pixels (away from colour edges) of the centre-eye render that are
// off the closed form by more than 0.05: checker colour along T_ray(d), times Lambert.
double closedFormError(const RenderResult& result, const DisplayConfig& config, bool flatShaded,
                       double zoom) {
  const test::DirectionColor expected = [&](glm::dvec3 d) -> std::optional<glm::vec3> {
    const auto v = test::scaleStereographic(glm::normalize(d), zoom);
    const glm::dvec3 a = glm::abs(v);
    // Flat cube faces shade with the face normal; the sphere's normals point at the viewer.
    return checkerSphereColor(v) * float(flatShaded ? std::max({a.x, a.y, a.z}) : 1.0);
  };
  std::size_t bad = 0, compared = 0;
  for (const WallImage& image : result.images) {
    const test::AnalyticComparison c = test::compareAnalytic(
        image.image, config.wall(image.wall), config.reference, expected, 0.05f);
    bad += c.bad;
    compared += c.unambiguous;
  }
  return compared ? double(bad) / double(compared) : 1.0;
}

// The checker-sphere with about `triangles` triangles; sharp textures (64 texels a square) so
// that texture filtering stays below a pixel in the closed-form comparison.
Scene sphereWithTriangles(std::size_t triangles) {
  BuiltinSceneOptions options;
  options.subdivision = std::max(1, int(std::lround(std::sqrt(triangles / 12.0))));
  options.texelsPerSquare = 64;
  return builtinScene("checker-sphere", options);
}

// The checker-sphere's n x n grid per face put back onto the cube, without normals: planar faces
// with exact checker uv and triangles of 90/n degrees that bend visibly under the squeeze.
Scene checkerCube(int n) {
  BuiltinSceneOptions options;
  options.subdivision = n;
  options.texelsPerSquare = 64;
  Scene cube = builtinScene("checker-sphere", options);
  for (Mesh& mesh : cube.meshes) {
    for (glm::vec3& p : mesh.positions) {
      const glm::vec3 a = glm::abs(p);
      p *= 10.0f / std::max({a.x, a.y, a.z});
    }
    mesh.normals.clear();
  }
  return cube;
}

// Share of all walls' pixels where two renders differ by more than 0.1 in some channel (the
// tolerance of the Vulkan/Embree cross-check test).
double imageDifference(const RenderResult& a, const RenderResult& b) {
  std::size_t bad = 0, pixels = 0;
  for (std::size_t i = 0; i < a.images.size() && i < b.images.size(); ++i) {
    const test::PixelComparison c = test::comparePixels(a.images[i].image, b.images[i].image, 0.1f);
    bad += c.bad;
    pixels += c.pixels;
  }
  return pixels ? double(bad) / double(pixels) : 1.0;
}

// Share of pixels nothing was drawn on: gaps, since the checker-sphere surrounds every wall.
double gapFraction(const RenderResult& result) {
  std::size_t gaps = 0, pixels = 0;
  for (const WallImage& image : result.images) {
    for (int y = 0; y < image.image.height; ++y)
      for (int x = 0; x < image.image.width; ++x) gaps += image.image.at(x, y)[3] < 0.5f;
    pixels += image.image.pixelCount();
  }
  return pixels ? double(gaps) / double(pixels) : 0.0;
}

// Tessellation thresholds of the sweeps in pixels (0: no tessellation); --thresholds replaces them.
std::vector<double> sweepThresholds = {0.125, 0.25, 0.5, 1.0, 2.0, 4.0, 0.0};

// Writes every wall of `result` as DIR/PREFIX-WALL.png, and where `reference` is given a mask of
// the pixels off it by more than 0.1 (white) as DIR/PREFIX-WALL-off.png; nothing without DIR.
void saveImages(const std::filesystem::path& dir, const std::string& prefix,
                const RenderResult& result, const RenderResult* reference) {
  if (dir.empty()) return;
  std::filesystem::create_directories(dir);
  for (std::size_t i = 0; i < result.images.size(); ++i) {
    const WallImage& image = result.images[i];
    writePng(dir / (prefix + "-" + image.wall + ".png"), image.image);
    if (!reference || i >= reference->images.size()) continue;
    const ImageRGBA& other = reference->images[i].image;
    if (other.width != image.image.width || other.height != image.image.height) continue;
    ImageRGBA mask = image.image;
    for (int y = 0; y < mask.height; ++y)
      for (int x = 0; x < mask.width; ++x) {
        float off = 0.0f;
        for (int c = 0; c < 4; ++c)
          off = std::max(off, std::abs(image.image.at(x, y)[c] - other.at(x, y)[c]));
        const float v = off > 0.1f ? 1.0f : 0.0f;
        float* m = mask.at(x, y);
        m[0] = m[1] = m[2] = v;
        m[3] = 1.0f;
      }
    writePng(dir / (prefix + "-" + image.wall + "-off.png"), mask);
  }
}

std::string thresholdName(double error) {
  return error > 0 ? std::to_string(error).substr(0, 5) : "no tess";
}

Timing timeThreshold(const VulkanOptions& options, double error, const Scene& scene,
                     const DisplayConfig& config, const RetargetMap& map,
                     const RenderSettings& settings, int repeats) {
  VulkanOptions sweep = options;
  sweep.tessellate = error > 0.0;
  sweep.tessellationErrorPixels = error > 0.0 ? error : 1.0;
  auto backend = makeVulkanBackend(sweep);
  backend->setScene(scene);
  return timeFrames(*backend, config, &map, settings, repeats);
}

// Threshold sweep under the config's real baked map, centre eye at the reference point: frame
// time relative to plain and the share of pixels off Embree's render (when not skipped).
// Returns the device's name.
std::string bakedMapSweep(const VulkanOptions& options, const DisplayConfig& config,
                          std::size_t triangles, double scale,
                          int bakeResolution, bool skipEmbree, int repeats,
                          const std::filesystem::path& imageDir) {
  BakeDisplayOptions bakeOptions;
  bakeOptions.useCache = false;
  bakeOptions.resolution = bakeResolution;
  const RetargetMap map = bakeDisplay(config, bakeOptions).map;
  const Scene scene = sphereWithTriangles(triangles);
  RenderSettings settings;
  settings.resolutionScale = scale;
  settings.head.position = config.reference;
  settings.camera.position = config.reference;
  std::optional<RenderResult> embree;
  if (!skipEmbree) {
    EmbreeBackend backend;
    backend.setScene(scene);
    embree = backend.render(config, &map, settings);
    saveImages(imageDir, "embree", *embree, nullptr);
  }
  settings.mode = RenderMode::Plain;
  auto backend = makeVulkanBackend(options);
  backend->setScene(scene);
  const Timing plain = timeFrames(*backend, config, nullptr, settings, repeats);
  settings.mode = RenderMode::Conformal;
  std::printf("\nsphere of %zu triangles under the baked %s map (%d texels a face), by "
              "tessellation threshold\n%-10s %9s %7s %9s %7s %9s %7s %12s %8s %12s %8s\n",
              scene.triangleCount(), config.name.c_str(), bakeResolution, "error px", "conf s",
              "ratio", "conf cpu", "ratio", "conf gpu", "ratio", "off Embree", "gaps",
              "tessellated", "with GS");
  for (double error : sweepThresholds) {
    const Timing t = timeThreshold(options, error, scene, config, map, settings, repeats);
    saveImages(imageDir, error > 0.0 ? "vulkan-" + thresholdName(error) + "px" : "vulkan-untessellated",
               t.last, embree ? &*embree : nullptr);
    char offEmbree[16] = "-";
    if (embree)
      std::snprintf(offEmbree, sizeof offEmbree, "%.2f%%",
                    100.0 * imageDifference(t.last, *embree));
    std::printf("%-10s %9.4f %7.2f %9.4f %7.2f %9.5f %7.2f %12s %7.2f%% %12zu %8zu\n",
                thresholdName(error).c_str(), t.seconds, t.seconds / plain.seconds, t.cpu,
                t.cpu / plain.cpu, t.gpu, plain.gpu > 0.0 ? t.gpu / plain.gpu : 0.0, offEmbree,
                100.0 * gapFraction(t.last),
                prepassOf(t.last).trianglesTessellated,
                prepassOf(t.last).trianglesThroughGeometryShader);
    std::fflush(stdout);
  }
  return deviceOf(plain.last);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("Vulkan backend: conformal/plain frame time and the tessellation threshold");
  std::string device, configName = "cave5";
  double scale = 0.25;
  int repeats = 3;
  int bakeResolution = 128;
  std::string imageDir;
  std::vector<std::size_t> extraSizes;
  std::size_t sweepTriangles = 20000;
  double errorPixels = VulkanOptions{}.tessellationErrorPixels;
  std::vector<std::string> mapNames = {"identity", "zoom", "squeeze", "baked"};
  bool skip1m = false, skip20k = false, skipSweep = false, skipZoomSweep = false,
       skipEmbree = false, timePasses = false;
  app.add_option("--device", device, "Vulkan device (name part or index; default: auto)");
  app.add_option("--config", configName, "display config in configs/ (name or path)");
  app.add_option("--scale", scale, "resolution scale of the walls")->check(CLI::PositiveNumber);
  app.add_option("--repeats", repeats, "timed frames per measurement (median)")
      ->check(CLI::PositiveNumber);
  app.add_flag("--skip-1m", skip1m, "leave out the ~1M-triangle scene");
  app.add_flag("--skip-20k", skip20k, "leave the ~20k-triangle scene out of the timing table");
  app.add_option("--triangles", extraSizes,
                 "more checker-sphere sizes for the timing table (about this many triangles)")
      ->delimiter(',');
  app.add_option("--maps", mapNames, "maps of the timing table (identity, zoom, squeeze, baked)")
      ->delimiter(',')
      ->check(CLI::IsMember({"identity", "zoom", "squeeze", "baked"}));
  app.add_option("--error-pixels", errorPixels,
                 "tessellation error bound of the timing table, pixels")
      ->check(CLI::PositiveNumber);
  app.add_option("--sweep-triangles", sweepTriangles,
                 "checker-sphere size of the baked-map sweep (about this many triangles)")
      ->check(CLI::PositiveNumber);
  app.add_flag("--skip-sweep", skipSweep, "leave out the threshold sweeps");
  bool stereo = false;
  app.add_flag("--stereo", stereo,
               "both stereo eyes in the timing table (conformal stereo against plain stereo)");
  app.add_flag("--skip-zoom-sweep", skipZoomSweep,
               "leave out the threshold sweeps under the zoom map (keep the baked-map one)");
  app.add_option("--thresholds", sweepThresholds,
                 "tessellation thresholds of the sweeps in pixels, 0 for none")
      ->delimiter(',');
  app.add_flag("--skip-embree", skipEmbree,
               "no Embree render in the baked-map sweep (no image difference column)");
  app.add_flag("--time-passes", timePasses,
               "time each pass of the pre-pass (GPU time, median ms) below each row of the timing "
               "table; the timestamps between them slow the navigating frame slightly");
  std::string flatCull = "auto";
  app.add_option("--flat-cull", flatCull,
                 "cull the pre-pass's flat list per wall: on, off, or auto (on for GPUs; "
                 "VulkanOptions::cullFlatListPerWall)")
      ->check(CLI::IsMember({"auto", "on", "off"}));
  app.add_option("--bake-resolution", bakeResolution, "texels per face of the baked map")
      ->check(CLI::PositiveNumber);
  app.add_option("--save-images", imageDir,
                 "write the baked-map sweep's renders (and masks of the pixels off Embree) as PNG "
                 "files into this directory");
  CLI11_PARSE(app, argc, argv);
  try {
    const std::filesystem::path configPath =
        std::filesystem::exists(configName)
            ? std::filesystem::path(configName)
            : std::filesystem::path(CONFVIS_SOURCE_DIR) / "configs" / (configName + ".json");
    const DisplayConfig config = loadDisplayConfig(configPath);
    VulkanOptions options;
    options.device = device;
    // Every timed frame runs the pre-pass, as a frame that navigates does; the timing table's
    // "reused" column is the frame that only moves the head (VulkanOptions::reusePrepass).
    options.reusePrepass = false;
    options.tessellationErrorPixels = errorPixels;
    if (flatCull != "auto") options.cullFlatListPerWall = flatCull == "on";
    VulkanOptions navigatingOptions = options;
    navigatingOptions.timePrepassPasses = timePasses;
    auto backend = makeVulkanBackend(navigatingOptions);
    VulkanOptions reuseOptions = options;
    reuseOptions.reusePrepass = true;
    auto reuseBackend = makeVulkanBackend(reuseOptions);
    RenderSettings settings;
    settings.resolutionScale = scale;
    if (stereo) settings.eyes = {Eye::Left, Eye::Right};
    const RetargetMap identity = RetargetMap::identity(256);
    const RetargetMap squeeze = test::azimuthSqueezeMap(256);
    constexpr double kZoom = 2.0;
    const RetargetMap zoom = test::zoomMap(256, kZoom);
    // The config's real map (the cut, its rim) at the default threshold, beside the smooth ones.
    BakeDisplayOptions bakeOptions;
    bakeOptions.useCache = false;
    bakeOptions.resolution = bakeResolution;
    const RetargetMap baked = bakeDisplay(config, bakeOptions).map;

    std::vector<std::pair<std::string, std::size_t>> scenes;
    if (!skip20k) scenes.push_back({"sphere-20k", 20000});
    if (!skip1m) scenes.push_back({"sphere-1M", 1000000});
    for (std::size_t size : extraSizes) scenes.push_back({"sphere-" + std::to_string(size), size});
    std::printf("config %s, %zu walls at scale %.3g (%d x %d px)%s, median of %d frames\n",
                config.name.c_str(), config.walls.size(), scale,
                int(std::lround(config.walls[0].width * scale)),
                int(std::lround(config.walls[0].height * scale)),
                stereo ? ", both stereo eyes" : "", repeats);
    std::printf("\n%-12s %10s %-9s %9s %9s %7s %9s %9s %7s %9s %9s %7s %9s %11s %9s %8s %14s "
                "%9s\n",
                "scene", "triangles", "map", "plain s", "conf s", "ratio", "plain cpu",
                "conf cpu", "ratio", "plain gpu", "conf gpu", "ratio", "prepass s", "prepass gpu",
                "tess",
                "with GS", "reused: ratio", "gpu");
    for (const auto& [name, triangles] : scenes) {
      const Scene scene = sphereWithTriangles(triangles);
      backend->setScene(scene);
      reuseBackend->setScene(scene);
      for (const auto& [mapName, map] :
           {std::pair<const char*, const RetargetMap*>{"identity", &identity},
            {"zoom", &zoom},
            {"squeeze", &squeeze},
            {"baked", &baked}}) {
        if (std::find(mapNames.begin(), mapNames.end(), mapName) == mapNames.end()) continue;
        // Plain, conformal and the reused pre-pass, a frame each in turn.
        const std::vector<Timing> t = timeInterleaved(
            {{backend.get(), nullptr}, {backend.get(), map}, {reuseBackend.get(), map}}, config,
            settings, repeats);
        const Timing &plain = t[0], &conformal = t[1], &reused = t[2];
        device = deviceOf(plain.last);
        std::printf("%-12s %10zu %-9s %9.4f %9.4f %7.2f %9.4f %9.4f %7.2f %9.5f %9.5f %7.2f "
                    "%9.4f %11.5f %9zu %8zu %14.2f %9.2f\n",
                    name.c_str(), scene.triangleCount(), mapName, plain.seconds,
                    conformal.seconds, pairedRatio(conformal.wall, plain.wall), plain.cpu,
                    conformal.cpu, pairedRatio(conformal.cpuFrames, plain.cpuFrames), plain.gpu,
                    conformal.gpu, pairedRatio(conformal.gpuFrames, plain.gpuFrames),
                    prepassOf(conformal.last).prepassSeconds,
                    prepassOf(conformal.last).prepassGpuSeconds.value_or(0.0),
                    prepassOf(conformal.last).trianglesTessellated,
                    prepassOf(conformal.last).trianglesThroughGeometryShader,
                    pairedRatio(reused.wall, plain.wall),
                    pairedRatio(reused.gpuFrames, plain.gpuFrames));
        if (!conformal.passFrames.empty()) {
          std::printf("  pre-pass passes, GPU ms:");
          for (const auto& [pass, seconds] : conformal.passFrames)
            std::printf(" %s %.2f", pass.c_str(), 1e3 * median(seconds));
          std::printf("\n");
        }
        std::fflush(stdout);
      }
    }

    // Threshold sweep under the smooth conformal map: frame time relative to plain, and the share
    // of pixels off the closed form.
    for (const auto& [sceneName, flat] :
         {std::pair<const char*, bool>{"sphere-20k", false}, {"cube-4x4", true}}) {
      if (skipSweep || skipZoomSweep) break;
      const Scene scene = flat ? checkerCube(4) : sphereWithTriangles(20000);
      std::printf("\n%s under the zoom map, by tessellation threshold\n%-10s %9s %7s %9s %7s "
                  "%9s %7s %18s %12s\n",
                  sceneName, "error px", "conf s", "ratio", "conf cpu", "ratio", "conf gpu",
                  "ratio", "off closed form", "tessellated");
      settings.mode = RenderMode::Plain;
      backend->setScene(scene);
      const Timing plain = timeFrames(*backend, config, nullptr, settings, repeats);
      settings.mode = RenderMode::Conformal;
      for (double error : sweepThresholds) {
        const Timing t = timeThreshold(options, error, scene, config, zoom, settings, repeats);
        std::printf("%-10s %9.4f %7.2f %9.4f %7.2f %9.5f %7.2f %17.2f%% %12zu\n",
                    thresholdName(error).c_str(), t.seconds, t.seconds / plain.seconds, t.cpu,
                    t.cpu / plain.cpu, t.gpu, plain.gpu > 0.0 ? t.gpu / plain.gpu : 0.0,
                    100.0 * closedFormError(t.last, config, flat, kZoom),
                    prepassOf(t.last).trianglesTessellated);
        std::fflush(stdout);
      }
    }
    if (!skipSweep)
      device = bakedMapSweep(options, config, sweepTriangles, scale, bakeResolution, skipEmbree,
                             repeats, imageDir);
    std::printf("\ndevice: %s\n", device.c_str());
  } catch (const Error& e) {
    std::fprintf(stderr, "confvis_bench_vulkan: %s\n", e.what());
    return 1;
  }
  return 0;
}
