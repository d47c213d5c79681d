// Bake benchmark (run by hand, never in CI): time from a display config to both cube maps in
// memory (computeDisplayMap + bakeRetargetMap), split into template, flow, alignment and bake,
// per refinement edge length and cube-map resolution, at the config's reference point and at a
// moved one (a tracked head). The baseline, measured in the same run, is filling both maps with
// the identity (RetargetMap::identity, one thread): the least a bake at that resolution must do.
// Wall times (ms) per stage, and the process CPU time of the whole run and of the bake alone.
// Each run bakes twice from the same display map: once into fresh cube maps (bakeRetargetMap)
// and once into the previous run's maps (bakeRetargetMapInto, as a tracked head re-bakes); the
// total is config -> template -> flow -> alignment -> reused bake. CPU columns give min/mean.
//
//   build/confvis_bench_bake [--config configs/cave5.json] [--edges 0.2,0.1,0.05]
//                            [--resolutions 256,512,1024] [--repeat 5] [--threads 0]
//                            [--route spherical|euclidean] [--preset fast|accurate]
// --preset takes the preset's route (unless --route is given) and grading (bake_preset.hpp) and,
// without --edges, its edge length (the preset's scale of the config's edge_length).
#include <CLI/CLI.hpp>
#include <sys/resource.h>

#include <algorithm>
#include <optional>
#include <cstdio>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "confvis/base/stopwatch.hpp"
#include "confvis/conformal/bake.hpp"
#include "confvis/conformal/bake_display.hpp"
#include "confvis/conformal/bake_preset.hpp"
#include "confvis/conformal/baked_map_quality.hpp"
#include "confvis/conformal/display_map.hpp"
#include "confvis/engine/display_config.hpp"

using namespace confvis;

namespace {

// CPU seconds of the whole process (all threads): on a shared machine wall times inflate with
// the load, CPU time much less.
double processCpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec +
         1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

template <class T>
std::vector<T> parseList(const std::string& text) {
  std::vector<T> values;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) values.push_back(static_cast<T>(std::stod(item)));
  return values;
}

std::vector<std::string> splitNames(const std::string& text) {
  std::vector<std::string> names;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) names.push_back(item);
  return names;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

double stage(const DisplayMap& map, const char* key) {
  return map.stats.contains(key) && map.stats[key].is_number() ? map.stats[key].get<double>() : 0;
}

struct Sample {
  double templ = 0, flow = 0, alignment = 0, bake = 0, locators = 0, ray = 0, geom = 0, extend = 0, total = 0;
  double cpu = 0, bakeCpu = 0, freshBakeCpu = 0;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"confvis bake benchmark: config -> both cube maps in memory"};
  std::string configPath = std::string(CONFVIS_SOURCE_DIR) + "/configs/cave5.json";
  std::string edges = "0.2,0.1,0.05", resolutions = "256,512,1024";
  int repeat = 5, threads = 0;
  app.add_option("--config", configPath, "Display config")->capture_default_str();
  app.add_option("--edges", edges, "Refinement edge lengths, metres")->capture_default_str();
  app.add_option("--resolutions", resolutions, "Cube-map face sizes")->capture_default_str();
  app.add_option("--repeat", repeat, "Runs per row (median wall times; CPU min/mean)")->capture_default_str();
  app.add_option("--threads", threads, "Bake threads (0: one per core)")->capture_default_str();
  std::string route = "spherical";
  auto* routeOption =
      app.add_option("--route", route,
                     "Disk-map route of the display map: spherical | euclidean (default: the "
                     "preset's for the display, else spherical)")
          ->check(CLI::IsMember({"spherical", "euclidean"}))
          ->capture_default_str();
  std::string presetName;
  app.add_option("--preset", presetName, "Bake preset: fast | accurate (route, grading, edges)")
      ->check(CLI::IsMember({"fast", "accurate"}));
  auto* edgesOption = app.get_option("--edges");
  std::string interpolations = "linear";
  auto* interpolationsOption =
      app.add_option("--interpolations", interpolations,
                     "Map interpolations, comma-separated: linear, mobius (one row each; "
                     "default: the preset's, else linear)")
          ->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  const DisplayConfig base = loadDisplayConfig(configPath);
  std::optional<BakePresetSettings> preset;
  if (!presetName.empty()) {
    preset = presetSettings(parseBakePreset(presetName), base);
    if (edgesOption->count() == 0) edges = std::to_string(preset->edgeScale * base.edgeLength);
    if (interpolationsOption->count() == 0) interpolations = toString(preset->interpolation);
    std::printf("preset %s: %s\n", presetName.c_str(),
                mapSettingsJson(preset->route, preset->grading, preset->interpolation).dump().c_str());
  }
  const Vec3d moved{0.15, 0.1, -0.2};  // a head 27 cm off centre
  std::printf("config %s, %u hardware threads, bake threads %d, median of %d runs; times in ms\n",
              configPath.c_str(), std::thread::hardware_concurrency(), threads, repeat);
  std::printf("%-6s %5s %-9s %6s %6s | %8s %8s %9s %8s (%6s %6s %6s %6s) | %8s | %15s %15s %15s | %8s %6s | %s\n",
              "edge", "res", "reference", "S tris", "T tris", "template", "flow", "alignment",
              "bake", "loc", "ray", "geom", "extend", "total", "cpu min/mean", "bake cpu min/mn",
              "fresh bake cpu", "baseline", "bake/b", "ray ratio p50/p95/max, flipped");
  for (double edge : parseList<double>(edges))
    for (int n : parseList<int>(resolutions))
      for (const bool movedReference : {false, true})
        for (const std::string& interpolation : splitNames(interpolations)) {
        BakeDisplayOptions overrides;
        overrides.edgeLength = edge;
        overrides.resolution = n;
        if (movedReference) overrides.reference = moved;
        const DisplayConfig config = effectiveBakeConfig(base, overrides);
        std::vector<Sample> samples;
        DisplayMap last;
        RetargetMap map;  // as left by the previous frame's bake
        map.ray = CubeMap(n);
        map.geom = CubeMap(n);
        for (int r = 0; r < repeat; ++r) {
          const auto start = SteadyClock::now();
          const double cpuStart = processCpuSeconds();
          DisplayMapOptions mapOptions;
          mapOptions.route =
              route == "euclidean" ? DisplayMapRoute::Euclidean : DisplayMapRoute::Spherical;
          if (preset) {
            mapOptions.grading = preset->grading;
            if (routeOption->count() == 0) mapOptions.route = preset->route;
          }
          last = computeDisplayMap(config, mapOptions);
          const double bakeCpuStart = processCpuSeconds();
          BakeOptions bake;
          bake.reference = {config.reference.x, config.reference.y, config.reference.z};
          bake.threads = threads;
          bake.interpolation = parseMapInterpolation(interpolation);
          BakeTimings t;
          bakeRetargetMapInto(last, n, bake, map, &t);
          Sample s;
          s.total = secondsSince(start);
          s.cpu = processCpuSeconds() - cpuStart;
          s.bakeCpu = processCpuSeconds() - bakeCpuStart;
          const double freshStart = processCpuSeconds();
          const RetargetMap fresh = bakeRetargetMap(last, n, bake);
          s.freshBakeCpu = processCpuSeconds() - freshStart;
          s.templ = stage(last, "template");
          s.flow = stage(last, "flow");
          s.alignment = stage(last, "alignment");
          s.bake = t.total;
          s.ray = t.ray;
          s.geom = t.geom;
          s.locators = t.locators;
          s.extend = t.extend;
          samples.push_back(s);
        }
        std::vector<double> baseline;
        for (int r = 0; r < std::max(3, repeat); ++r) {
          const auto start = SteadyClock::now();
          const RetargetMap identity = RetargetMap::identity(n);
          baseline.push_back(secondsSince(start));
        }
        auto med = [&](double Sample::*field) {
          std::vector<double> v;
          for (const Sample& s : samples) v.push_back(s.*field * 1e3);
          return median(v);
        };
        auto minMean = [&](double Sample::*field) {
          double lo = 1e300, sum = 0;
          for (const Sample& s : samples) lo = std::min(lo, s.*field * 1e3), sum += s.*field * 1e3;
          char text[32];
          std::snprintf(text, sizeof text, "%.1f/%.1f", lo, sum / static_cast<double>(samples.size()));
          return std::string(text);
        };
        const BakedConformality q =
            measureBakedConformality(map.ray, {.margin = 2, .discontinuityTolerance = 0.5, .stride = std::max(1, n / 256)});
        std::printf("%-6.2f %5d %-9s %6zu %6zu | %8.2f %8.2f %9.2f %8.2f (%6.2f %6.2f %6.2f %6.2f) | %8.2f | %15s %15s %15s | %8.2f %6.2f | %.4f/%.4f/%.3f, %zu\n",
                    edge, n,
                    ((movedReference ? "moved/" : "config/") + interpolation.substr(0, 3)).c_str(),
                    last.source.triangles.size(),
                    last.target.triangles.size(), med(&Sample::templ), med(&Sample::flow),
                    med(&Sample::alignment), med(&Sample::bake), med(&Sample::locators), med(&Sample::ray),
                    med(&Sample::geom), med(&Sample::extend), med(&Sample::total),
                    minMean(&Sample::cpu).c_str(), minMean(&Sample::bakeCpu).c_str(),
                    minMean(&Sample::freshBakeCpu).c_str(),
                    median(baseline) * 1e3, med(&Sample::bake) / (median(baseline) * 1e3),
                    q.ratioP50, q.ratioP95, q.ratioMax, q.flipped);
        std::fflush(stdout);
      }
  return 0;
}
