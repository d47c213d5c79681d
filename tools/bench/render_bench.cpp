// Render benchmark (run by hand, never in CI). In one run, on one scene and resolution:
//   - conformal / plain render time of the Embree backend (goal <= 1.05),
//   - the backend's rays per second against a bare rtcIntersect8 loop over the same scene and
//     the same primary rays (goal >= 80 %), and the conformal render's against the same loop
//     over its own (conformal) rays,
//   - the image-based alternative (render a cube map around c, resample it through the same
//     map, as SGCT's fisheye path does) at equal output resolution: time, and sharpness as PSNR
//     against a 16-spp conformal reference, next to the direct (ray-retargeted) render.
// Stereo timings (exact curved rays, fast straight rays) are reported alongside.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>

#include "confvis/backends/analytic_maps.hpp"
#include "confvis/backends/conformal_warp.hpp"
#include "confvis/backends/embree/embree_backend.hpp"
#include "confvis/backends/retarget_map_files.hpp"
#include "confvis/base/atomic_file.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/stopwatch.hpp"
#include "confvis/conformal/display_template.hpp"
#include "confvis/engine/builtin_scenes.hpp"
#include "confvis/engine/scene_loader.hpp"
#include "image_based_retarget.hpp"
#include "raw_intersect_loop.hpp"

using namespace confvis;

namespace {

double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Best of `repeats` wall-clock timings of f.
double bestSeconds(int repeats, const std::function<void()>& f) {
  double best = 1e30;
  for (int i = 0; i < repeats; ++i) {
    const auto start = SteadyClock::now();
    f();
    best = std::min(best, secondsSince(start));
  }
  return best;
}

// PSNR (dB, peak 1) of the RGB of `images` against `reference`, values clamped to [0, 1].
double psnr(const std::vector<WallImage>& images, const std::vector<WallImage>& reference) {
  double squared = 0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < images.size(); ++i) {
    const ImageRGBA& a = images[i].image;
    const ImageRGBA& b = reference[i].image;
    for (std::size_t p = 0; p < a.pixelCount(); ++p)
      for (int c = 0; c < 3; ++c) {
        const double d = std::clamp(a.pixels[4 * p + c], 0.0f, 1.0f) -
                         std::clamp(b.pixels[4 * p + c], 0.0f, 1.0f);
        squared += d * d;
        ++count;
      }
  }
  const double mse = squared / static_cast<double>(count);
  return mse > 0 ? 10.0 * std::log10(1.0 / mse) : INFINITY;
}

// Mean luminance gradient (|dx| + |dy|) of the images relative to the reference's: blur lowers
// it below 1, aliasing raises it above 1.
double sharpness(const std::vector<WallImage>& images, const std::vector<WallImage>& reference) {
  auto gradient = [](const std::vector<WallImage>& set) {
    double sum = 0;
    std::size_t n = 0;
    for (const WallImage& wall : set) {
      const ImageRGBA& im = wall.image;
      auto luminance = [&](int x, int y) {
        const float* p = im.at(x, y);
        return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
      };
      for (int y = 0; y + 1 < im.height; ++y)
        for (int x = 0; x + 1 < im.width; ++x, ++n)
          sum += std::abs(luminance(x + 1, y) - luminance(x, y)) +
                 std::abs(luminance(x, y + 1) - luminance(x, y));
    }
    return sum / static_cast<double>(n);
  };
  return gradient(images) / gradient(reference);
}

struct StereoSeconds {
  double plain = 1e30, exact = 1e30, fast = 1e30, exactMoving = 1e30, fastMoving = 1e30;
};

// Stereo frames (both eyes of every wall) as a frame loop renders them (renderInto, interleaved
// repeats, best of each): plain, conformal with exact and with fast stereo rays, each with the
// head still (from the second frame on the eyes' ray tables are read) and with a head that moves
// every frame (by 0.1 mm: no exact tails' table is ever reused, their tails are computed per
// packet; fast rays read the table of targets W(p), which serves every head).
StereoSeconds stereoFigures(EmbreeBackend& backend, const DisplayConfig& config,
                            const RetargetMap& map, const RenderSettings& plain,
                            const RenderSettings& conformal, int repeats) {
  RenderSettings plainStereo = plain, exactStereo = conformal, fastStereo = conformal;
  plainStereo.eyes = exactStereo.eyes = fastStereo.eyes = {Eye::Left, Eye::Right};
  fastStereo.stereoRays = StereoRays::Fast;
  RenderResult plainFrame, exactFrame, fastFrame, movingFrame;
  // Warm-up: the still head's tables are built on its second frame.
  for (int i = 0; i < 2; ++i) {
    backend.renderInto(config, &map, exactStereo, exactFrame);
    backend.renderInto(config, &map, fastStereo, fastFrame);
  }
  backend.renderInto(config, nullptr, plainStereo, plainFrame);
  StereoSeconds best;
  const auto timed = [](double& seconds, const std::function<void()>& f) {
    const auto start = SteadyClock::now();
    f();
    seconds = std::min(seconds, secondsSince(start));
  };
  for (int i = 0; i < repeats; ++i) {
    timed(best.plain, [&] { backend.renderInto(config, nullptr, plainStereo, plainFrame); });
    timed(best.exact, [&] { backend.renderInto(config, &map, exactStereo, exactFrame); });
    timed(best.fast, [&] { backend.renderInto(config, &map, fastStereo, fastFrame); });
    RenderSettings exactMoving = exactStereo, fastMoving = fastStereo;
    exactMoving.head.position.x += 1e-4 * (i + 1);
    fastMoving.head.position.x -= 1e-4 * (i + 1);
    timed(best.exactMoving, [&] { backend.renderInto(config, &map, exactMoving, movingFrame); });
    timed(best.fastMoving, [&] { backend.renderInto(config, &map, fastMoving, movingFrame); });
  }
  std::printf("stereo     plain %.4f s, conformal exact %.4f s (x%.3f, goal <= 1.10), fast %.4f s "
              "(x%.3f, goal <= 1.05)\n",
              best.plain, best.exact, best.exact / best.plain, best.fast, best.fast / best.plain);
  std::printf("           a head moving every frame (exact: tails per packet, no table; fast: "
              "the eye-independent target table): exact %.4f s "
              "(x%.3f), fast %.4f s (x%.3f)\n",
              best.exactMoving, best.exactMoving / best.plain, best.fastMoving,
              best.fastMoving / best.plain);
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"confvis render benchmark: conformal vs plain, raw Embree, image-based retarget"};
  std::string configPath = std::string(CONFVIS_SOURCE_DIR) + "/configs/cave5.json";
  std::string sceneName = "checker-sphere", mapDirectory, jsonPath;
  double scale = 0.5, lambda = 1.5;
  int repeats = 3;
  app.add_option("--config", configPath, "Display config")->capture_default_str();
  app.add_option("--scene", sceneName, "Built-in scene or scene file")->capture_default_str();
  int subdivision = 0;
  app.add_option("--subdivision", subdivision,
                 "Built-in scene's mesh density (BuiltinSceneOptions::subdivision; checker-sphere: "
                 "12 n^2 triangles, 289 for ~1M); 0 = the scene's default")
      ->capture_default_str();
  app.add_option("--scale", scale, "Output resolution / wall resolution")->capture_default_str();
  app.add_option("--map", mapDirectory,
                 "Baked map directory; default: identity for a full-sphere display, otherwise "
                 "the analytic ceilingless dilation map");
  app.add_option("--lambda", lambda, "Dilation factor of the analytic map")->capture_default_str();
  app.add_option("--repeats", repeats, "Timed repetitions (best is reported)")->capture_default_str();
  app.add_option("--json", jsonPath, "Also write the figures as JSON");
  bool goalsOnly = false;
  app.add_flag("--goals-only", goalsOnly,
               "Only the goal figures (conformal/plain, % of raw); skip stereo and image-based");
  bool stereoOnly = false;
  app.add_flag("--stereo-only", stereoOnly, "Only the stereo figures (exact and fast stereo rays "
               "against plain stereo)");
  std::string profileMode;
  app.add_option("--profile", profileMode,
                 "Only render `repeats` frames of one kind after the "
                 "warm-up, for a profiler (perf, callgrind); prints nothing else")
      ->check(CLI::IsMember({"plain", "conformal", "raw", "plain-stereo", "exact-stereo", "exact-moving",
                        "fast-stereo", "fast-moving"}));
  EmbreeOptions embreeOptions;
  app.add_flag("--baseline-shading", embreeOptions.baselineShading,
               "The baseline (SSE2) shading code even where the CPU has AVX2");
  CLI11_PARSE(app, argc, argv);

  try {
    const DisplayConfig config = loadDisplayConfig(configPath);
    RetargetMap map;
    std::string mapName;
    if (!mapDirectory.empty()) {
      map = readRetargetMapDirectory(mapDirectory);
      mapName = mapDirectory;
    } else if (displayMapIsIdentity(config)) {
      map = RetargetMap::identity(config.cubeResolution, {config.reference.x, config.reference.y,
                                                          config.reference.z});
      mapName = "identity";
    } else {
      map = ceilinglessDilationMap(lambda, config.cubeResolution, config.reference);
      mapName = "analytic ceilingless dilation, lambda " + std::to_string(lambda);
    }
    BuiltinSceneOptions sceneOptions;
    sceneOptions.subdivision = subdivision;
    const Scene scene =
        subdivision > 0 ? builtinScene(sceneName, sceneOptions) : sceneByNameOrFile(sceneName);
    EmbreeBackend backend(embreeOptions);
    backend.setScene(scene);
    EmbreeDevice rawDevice;
    const EmbreeScene rawScene(rawDevice, scene);

    RenderSettings plain;
    plain.mode = RenderMode::Plain;
    plain.resolutionScale = scale;
    plain.head.position = plain.camera.position = config.reference;
    RenderSettings conformal = plain;
    conformal.mode = RenderMode::Conformal;

    const RenderResult warmUp = backend.render(config, &map, conformal);  // caches, TBB workers
    std::printf("display %s (%zu walls), scene %s (%zu triangles), map: %s, scale %.3g, %d "
                "repeats (best), shading %s\n",
                config.name.c_str(), config.walls.size(), scene.name.c_str(),
                scene.triangleCount(), mapName.c_str(), scale, repeats,
                warmUp.stats.embree->shadingSimd.c_str());
    if (!profileMode.empty()) {
      RenderResult frame;  // a frame loop's images, rendered over (renderInto)
      if (profileMode == "conformal") backend.render(config, &map, conformal);  // builds tables
      RenderSettings plainStereo = plain, exactStereo = conformal;
      plainStereo.eyes = exactStereo.eyes = {Eye::Left, Eye::Right};
      RenderSettings fastStereo = exactStereo;
      fastStereo.stereoRays = StereoRays::Fast;
      if (profileMode == "exact-stereo")
        for (int i = 0; i < 2; ++i) backend.render(config, &map, exactStereo);  // builds tables
      if (profileMode == "fast-stereo" || profileMode == "fast-moving")
        for (int i = 0; i < 2; ++i) backend.render(config, &map, fastStereo);  // builds tables
      for (int i = 0; i < repeats; ++i) {
        if (profileMode == "plain") backend.renderInto(config, nullptr, plain, frame);
        if (profileMode == "conformal") backend.renderInto(config, &map, conformal, frame);
        if (profileMode == "raw") bench::rawIntersectLoop(rawScene, config, scale);
        if (profileMode == "plain-stereo") backend.renderInto(config, nullptr, plainStereo, frame);
        if (profileMode == "exact-stereo") backend.renderInto(config, &map, exactStereo, frame);
        if (profileMode == "exact-moving") {  // a new head place every frame: no table
          exactStereo.head.position.x += 1e-4;
          backend.renderInto(config, &map, exactStereo, frame);
        }
        if (profileMode == "fast-stereo") backend.renderInto(config, &map, fastStereo, frame);
        if (profileMode == "fast-moving") {
          fastStereo.head.position.x += 1e-4;
          backend.renderInto(config, &map, fastStereo, frame);
        }
      }
      return 0;
    }

    if (stereoOnly) {
      stereoFigures(backend, config, map, plain, conformal, repeats);
      return 0;
    }

    // Frames as a frame loop renders them: each into the previous frame's images (renderInto),
    // so no frame allocates or faults in fresh output memory. One plain frame per repeat is
    // also rendered by value (fresh images) and reported on its own.
    RenderResult plainResult, conformalResult;
    double plainSeconds = 1e30, conformalSeconds = 1e30, rawSeconds = 1e30;
    // CPU seconds of the whole process (all threads): on a shared machine other processes steal
    // wall-clock time, not CPU time, so these ratios are the steadier ones.
    double plainCpu = 1e30, conformalCpu = 1e30, rawCpu = 1e30, freshPlainCpu = 1e30;
    double rawConformalSeconds = 1e30, rawConformalCpu = 1e30, raw16Seconds = 1e30;
    double raw16ConformalSeconds = 1e30, raw16PlainTableSeconds = 1e30;
    bench::RawLoopResult raw, rawConformal, raw16, raw16Conformal, raw16PlainTable;
    const bench::DirectionTables conformalRays = bench::conformalDirections(map, config, scale);
    const bench::DirectionTables plainRays = bench::plainDirections(config, scale);
    for (int i = 0; i < repeats; ++i) {  // interleaved, so load changes hit all alike
      double cpu = cpuSeconds();
      const RenderResult fresh = backend.render(config, nullptr, plain);
      freshPlainCpu = std::min(freshPlainCpu, cpuSeconds() - cpu);
      auto start = SteadyClock::now();
      cpu = cpuSeconds();
      backend.renderInto(config, nullptr, plain, plainResult);
      plainSeconds = std::min(plainSeconds, secondsSince(start));
      plainCpu = std::min(plainCpu, cpuSeconds() - cpu);
      start = SteadyClock::now();
      cpu = cpuSeconds();
      backend.renderInto(config, &map, conformal, conformalResult);
      conformalSeconds = std::min(conformalSeconds, secondsSince(start));
      conformalCpu = std::min(conformalCpu, cpuSeconds() - cpu);
      cpu = cpuSeconds();
      raw = bench::rawIntersectLoop(rawScene, config, scale);
      rawSeconds = std::min(rawSeconds, raw.seconds);
      rawCpu = std::min(rawCpu, cpuSeconds() - cpu);
      cpu = cpuSeconds();
      rawConformal = bench::rawIntersectLoop(rawScene, config, scale, &conformalRays);
      rawConformalSeconds = std::min(rawConformalSeconds, rawConformal.seconds);
      rawConformalCpu = std::min(rawConformalCpu, cpuSeconds() - cpu);
      raw16 = bench::rawIntersect16Loop(rawScene, config, scale);
      raw16Seconds = std::min(raw16Seconds, raw16.seconds);
      raw16Conformal = bench::rawIntersect16Loop(rawScene, config, scale, &conformalRays);
      raw16ConformalSeconds = std::min(raw16ConformalSeconds, raw16Conformal.seconds);
      raw16PlainTable = bench::rawIntersect16Loop(rawScene, config, scale, &plainRays);
      raw16PlainTableSeconds = std::min(raw16PlainTableSeconds, raw16PlainTable.seconds);
    }
    const double rays = static_cast<double>(plainResult.stats.embree->cameraRays);
    const double plainRate = rays / plainSeconds, conformalRate = rays / conformalSeconds;
    const double rawRate = static_cast<double>(raw.rays) / rawSeconds;
    std::printf("\nplain      %8.4f s  %7.2f Mrays/s  (%.0f rays, %.0f retraced)\n", plainSeconds,
                plainRate * 1e-6, rays,
                static_cast<double>(plainResult.stats.embree->retracedRays));
    std::printf("conformal  %8.4f s  %7.2f Mrays/s  conformal/plain time %.3f (goal <= 1.05)\n",
                conformalSeconds, conformalRate * 1e-6, conformalSeconds / plainSeconds);
    std::printf("raw rtcIntersect8 %8.4f s  %7.2f Mrays/s  plain %.0f %%, conformal %.0f %% of "
                "raw (goal >= 80 %%)\n",
                rawSeconds, rawRate * 1e-6, 100 * plainRate / rawRate, 100 * conformalRate / rawRate);
    std::printf("CPU time   plain %.4f s, conformal %.4f s (ratio %.3f), raw %.4f s: plain %.0f %%, "
                "conformal %.0f %% of raw rays per CPU second\n",
                plainCpu, conformalCpu, conformalCpu / plainCpu, rawCpu, 100 * rawCpu / plainCpu,
                100 * rawCpu / conformalCpu);
    std::printf("           plain by value (fresh images) %.4f s: %.0f %% of raw\n", freshPlainCpu,
                100 * rawCpu / freshPlainCpu);
    // The renderer traces two packets per rtcIntersect16: the same-width loop, like for like.
    const double raw16Rate = static_cast<double>(raw16.rays) / raw16Seconds;
    std::printf("raw rtcIntersect16 (the renderer's width) %8.4f s  %7.2f Mrays/s  plain %.0f %%, "
                "conformal %.0f %% of it\n",
                raw16Seconds, raw16Rate * 1e-6, 100 * plainRate / raw16Rate,
                100 * conformalRate / raw16Rate);
    // The same loop over the conformal frame's own rays (they cross the squeezed parts of the
    // scene: the fair ceiling of a conformal render, beside the plain-ray loop the goal names).
    const double conformalRayCount = static_cast<double>(conformalResult.stats.embree->cameraRays);
    const double rawConformalRate = static_cast<double>(rawConformal.rays) / rawConformalSeconds;
    std::printf("raw loop over the conformal rays %8.4f s (%.3f x the plain-ray loop): conformal "
                "render %.0f %% of its rate (CPU: %.4f s, %.0f %%)\n",
                rawConformalSeconds, rawConformalSeconds / rawSeconds,
                100 * (conformalRayCount / conformalSeconds) / rawConformalRate, rawConformalCpu,
                100 * (conformalRayCount / conformalCpu) /
                    (static_cast<double>(rawConformal.rays) / rawConformalCpu));
    // Both renders against the 16-wide loop over their own rays: what the renderer adds to
    // tracing, mode by mode. The conformal loop reads its directions from a table, as the
    // renderer does; the same loop over a table of the plain rays differs from it in the rays
    // alone, and from the computed plain loop in the table's reads.
    const double raw16ConformalRate =
        static_cast<double>(raw16Conformal.rays) / raw16ConformalSeconds;
    std::printf("raw rtcIntersect16 over the conformal rays %8.4f s: %.3f x the same loop over "
                "the plain rays from a table (the rays' own cost), %.3f x the plain-ray loop; "
                "conformal render %.0f %% of its rate, plain render %.0f %% of its own\n",
                raw16ConformalSeconds, raw16ConformalSeconds / raw16PlainTableSeconds,
                raw16ConformalSeconds / raw16Seconds,
                100 * (conformalRayCount / conformalSeconds) / raw16ConformalRate,
                100 * plainRate / raw16Rate);
    std::printf("raw rtcIntersect16 over the plain rays from a table %8.4f s: %.3f x the loop "
                "computing them (the table's reads)\n",
                raw16PlainTableSeconds, raw16PlainTableSeconds / raw16Seconds);
    // The first conformal render of an image looks the map up per sample; later ones read the
    // direction table built on the second (the warm-up render counts as the first).
    EmbreeBackend freshBackend;
    freshBackend.setScene(scene);
    const auto firstStart = SteadyClock::now();
    const RenderResult firstFrame = freshBackend.render(config, &map, conformal);
    const double firstFrameSeconds = secondsSince(firstStart);
    const RenderResult secondFrame = freshBackend.render(config, &map, conformal);
    std::printf("map: grids + tables built in %.4f s (first frame, %.4f s in all), table %.4f s "
                "(second frame); a frame reads %.0f table samples\n",
                firstFrame.stats.embree->mapBuildSeconds, firstFrameSeconds,
                secondFrame.stats.embree->mapBuildSeconds,
                static_cast<double>(conformalResult.stats.embree->directionTableSamples));
    nlohmann::json report = {
        {"display", config.name},
        {"scene", scene.name},
        {"triangles", scene.triangleCount()},
        {"map", mapName},
        {"scale", scale},
        {"threads", plainResult.stats.embree->threads},
        {"plain_seconds", plainSeconds},
        {"conformal_seconds", conformalSeconds},
        {"conformal_over_plain", conformalSeconds / plainSeconds},
        {"cpu_seconds",
         {{"plain", plainCpu}, {"conformal", conformalCpu}, {"raw", rawCpu},
          {"plain_by_value", freshPlainCpu}}},
        {"conformal_over_plain_cpu", conformalCpu / plainCpu},
        {"camera_rays", rays},
        {"raw_rtcintersect8_rays_per_second", rawRate},
        {"plain_rays_per_second", plainRate},
        {"conformal_rays_per_second", conformalRate},
        {"plain_fraction_of_raw", plainRate / rawRate},
        {"conformal_fraction_of_raw", conformalRate / rawRate},
        {"raw_conformal_rays_per_second", rawConformalRate},
        {"raw_rtcintersect16_rays_per_second", raw16Rate},
        {"raw_rtcintersect16_conformal_rays_per_second", raw16ConformalRate},
        {"conformal_fraction_of_raw_conformal", (conformalRayCount / conformalSeconds) / rawConformalRate},
        {"first_frame_map_build_seconds", firstFrame.stats.embree->mapBuildSeconds},
        {"second_frame_map_build_seconds", secondFrame.stats.embree->mapBuildSeconds}};
    if (goalsOnly) {
      if (!jsonPath.empty()) writeTextAtomically(jsonPath, report.dump(2) + "\n");
      return 0;
    }

    const StereoSeconds stereo = stereoFigures(backend, config, map, plain, conformal, repeats);

    // Sharpness against a 16-spp reference, at equal output resolution.
    RenderSettings reference = conformal;
    reference.samplesPerPixel = 16;
    const auto referenceStart = SteadyClock::now();
    const RenderResult referenceResult = backend.render(config, &map, reference);
    const double referenceSeconds = secondsSince(referenceStart);
    const double directPsnr = psnr(conformalResult.images, referenceResult.images);
    const double directSharpness = sharpness(conformalResult.images, referenceResult.images);
    std::printf("\n16-spp reference %.3f s; sharpness = mean gradient / the reference's (blur < 1 "
                "< aliasing)\n", referenceSeconds);
    std::printf("direct ray retarget, 1 spp:          %8.4f s  PSNR %.2f dB  sharpness %.3f\n",
                conformalSeconds, directPsnr, directSharpness);
    RenderSettings direct4 = conformal;
    direct4.samplesPerPixel = 4;
    RenderResult direct4Result;
    const double direct4Seconds =
        bestSeconds(repeats, [&] { direct4Result = backend.render(config, &map, direct4); });
    const double direct4Psnr = psnr(direct4Result.images, referenceResult.images);
    std::printf("direct ray retarget, 4 spp:          %8.4f s  PSNR %.2f dB  sharpness %.3f\n",
                direct4Seconds, direct4Psnr, sharpness(direct4Result.images, referenceResult.images));
    const ConformalWarp warp(map);
    const std::vector<WallMapGrid> grids = bench::wallGrids(config, warp, scale);
    const int wallPixels = std::max(1, static_cast<int>(std::lround(config.walls[0].width * scale)));
    nlohmann::json imageBased = nlohmann::json::array();
    for (int factor : {1, 2}) {
      const int faceSize = factor * wallPixels;
      bench::ImageBasedTimings timings, best{1e30, 1e30};
      std::vector<WallImage> images;
      for (int i = 0; i < repeats; ++i) {
        images = bench::renderImageBased(backend, config, grids, faceSize, scale, timings);
        if (timings.cubeSeconds + timings.resampleSeconds < best.cubeSeconds + best.resampleSeconds)
          best = timings;
      }
      const double total = best.cubeSeconds + best.resampleSeconds;
      const double value = psnr(images, referenceResult.images);
      const double crisp = sharpness(images, referenceResult.images);
      std::printf("image-based, cube %4d^2 x 6, 1 spp: %8.4f s  PSNR %.2f dB  sharpness %.3f  "
                  "(cube %.4f s + resample %.4f s; x%.2f the direct time)\n",
                  faceSize, total, value, crisp, best.cubeSeconds, best.resampleSeconds,
                  total / conformalSeconds);
      imageBased.push_back({{"cube_face_size", faceSize},
                            {"seconds", total},
                            {"cube_seconds", best.cubeSeconds},
                            {"resample_seconds", best.resampleSeconds},
                            {"psnr_db", value},
                            {"sharpness", crisp}});
    }
    report["stereo_seconds"] = {{"plain", stereo.plain},
                                {"exact", stereo.exact},
                                {"fast", stereo.fast},
                                {"exact_moving_head", stereo.exactMoving},
                                {"fast_moving_head", stereo.fastMoving}};
    report["reference_spp"] = 16;
    report["direct_psnr_db"] = directPsnr;
    report["direct_sharpness"] = directSharpness;
    report["direct_4spp_seconds"] = direct4Seconds;
    report["direct_4spp_psnr_db"] = direct4Psnr;
    report["image_based"] = imageBased;
    if (!jsonPath.empty()) {
      writeTextAtomically(jsonPath, report.dump(2) + "\n");
    }
  } catch (const Error& e) {
    std::fprintf(stderr, "confvis_bench_render: %s\n", e.what());
    return 2;
  }
  return 0;
}
