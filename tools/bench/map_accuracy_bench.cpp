// Map accuracy benchmark (issue 22, point 7; run by hand, never in CI): per display config, edge
// length and route, the map's error against a converged map (how far content moves on the wall,
// pixels of that wall: p50/p95/p99/max), the kink p99 of straight virtual lines where they cross
// element boundaries (degrees, 3 degrees around the singular corners left out), and the re-bake
// time (computeDisplayMap + bakeRetargetMapInto at the config's cube resolution, median wall ms).
// Measured on the piecewise-linear map itself (map_accuracy.hpp), so the cube-map resolution
// does not enter the error.
//
// The reference: the reference route at scale `--reference-start` x the config's edge length,
// halved until the p99 change between two levels is below --converge-px (or --reference-min is
// reached); every level is printed with its change. Reference maps are cached in --cache-dir
// (delete it after changing the map code: the key is the config, route, edge and kCacheVersion).
// With --reference-extrapolate the errors are measured against the Richardson extrapolation of
// the last two levels (map_reference_extrapolation.hpp): the order is estimated from the last
// three levels (or given by --reference-order), and each row adds the error against the finest
// level alone and the extrapolated reference's uncertainty.
//
//   nice -n 10 build/confvis_bench_map_accuracy [--configs configs/cave5.json,...]
//       [--scales 1,0.5,0.25] [--routes spherical,euclidean,hyperbolic] [--repeat 5]
#include <CLI/CLI.hpp>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "confvis/base/atomic_file.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/stopwatch.hpp"
#include "confvis/conformal/bake.hpp"
#include "confvis/conformal/bake_preset.hpp"
#include "confvis/conformal/display_map.hpp"
#include "confvis/conformal/map_accuracy.hpp"
#include "confvis/conformal/map_reference_extrapolation.hpp"
#include "confvis/engine/display_config.hpp"

using namespace confvis;

namespace {

// Bump when the map pipeline changes what a given config, route and edge produce.
constexpr const char* kCacheVersion = "map-accuracy-1";

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) items.push_back(item);
  return items;
}

DisplayMapRoute parseRoute(const std::string& name) {
  if (name == "spherical") return DisplayMapRoute::Spherical;
  if (name == "euclidean") return DisplayMapRoute::Euclidean;
  if (name == "hyperbolic") return DisplayMapRoute::Hyperbolic;
  throw Error(ErrorCode::InvalidInput, "unknown route '" + name + "' (spherical, euclidean, hyperbolic)");
}

template <class T>
void put(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}
template <class T>
void putVector(std::string& out, const std::vector<T>& v) {
  put(out, static_cast<std::uint64_t>(v.size()));
  out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}
template <class T>
T get(const std::string& in, std::size_t& at) {
  if (at + sizeof(T) > in.size()) throw Error(ErrorCode::InvalidInput, "truncated map cache");
  T value;
  std::memcpy(&value, in.data() + at, sizeof value);
  at += sizeof value;
  return value;
}
template <class T>
std::vector<T> getVector(const std::string& in, std::size_t& at) {
  const auto n = get<std::uint64_t>(in, at);
  if (at + n * sizeof(T) > in.size()) throw Error(ErrorCode::InvalidInput, "truncated map cache");
  std::vector<T> v(n);
  std::memcpy(v.data(), in.data() + at, n * sizeof(T));
  at += n * sizeof(T);
  return v;
}

std::string serialize(const DisplayMap& map) {
  std::string out = kCacheVersion;
  for (const SphereDiskMesh* mesh : {&map.source, &map.target}) {
    putVector(out, mesh->sphere);
    putVector(out, mesh->disk);
    putVector(out, mesh->triangles);
    putVector(out, mesh->boundary);
    putVector(out, mesh->lit);
  }
  return out;
}

DisplayMap deserialize(const std::string& in) {
  if (in.compare(0, std::strlen(kCacheVersion), kCacheVersion) != 0)
    throw Error(ErrorCode::InvalidInput, "map cache of another version");
  std::size_t at = std::strlen(kCacheVersion);
  DisplayMap map;
  for (SphereDiskMesh* mesh : {&map.source, &map.target}) {
    mesh->sphere = getVector<glm::dvec3>(in, at);
    mesh->disk = getVector<std::complex<double>>(in, at);
    mesh->triangles = getVector<std::array<int, 3>>(in, at);
    mesh->boundary = getVector<int>(in, at);
    mesh->lit = getVector<std::uint8_t>(in, at);
  }
  return map;
}

DisplayMap referenceMap(const DisplayConfig& config, DisplayMapRoute route,
                        const std::string& routeName, double edge, const TemplateGrading& grading,
                        const std::filesystem::path& cacheDir) {
  char name[200];
  std::snprintf(name, sizeof name, "%s-%s-%s-%.6f-g%.3f-%.3f-%.4f.bin", config.hash.c_str(),
                routeName.c_str(), kCacheVersion, edge, grading.radiusDegrees, grading.exponent,
                grading.minScale);
  const std::filesystem::path path = cacheDir / name;
  if (std::filesystem::exists(path)) {
    try {
      return deserialize(readTextFile(path));
    } catch (const Error&) {
      // recompute below
    }
  }
  const auto start = SteadyClock::now();
  DisplayMapOptions options;
  options.edgeLength = edge;
  options.route = route;
  options.grading = grading;
  DisplayMap map = computeDisplayMap(config, options);
  std::fprintf(stderr, "  reference %s %.4f m: %zu + %zu vertices, %.1f s\n", routeName.c_str(),
               edge, map.source.sphere.size(), map.target.sphere.size(),
               secondsSince(start));
  writeTextAtomically(path, serialize(map));
  return map;
}

// CPU seconds of the whole process (all threads): wall times inflate with a shared machine's load.
double processCpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec +
         1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

// The n worst samples against the extrapolated reference, each with the levels' changes there (a
// local order: log2 of two successive changes) and its angle to the nearest singular corner of
// the finest level (seen from the reference point).
void printWorstSamples(const DisplayConfig& config, const DisplayMapEvaluator& test,
                       std::span<const DisplayMapEvaluator* const> levels, const DisplayMap& finest,
                       double order, int samples, int threads, int n) {
  auto all = extrapolatedErrorSamples(config, test, levels, order, samples, threads);
  const auto count = std::min<std::size_t>(n, all.size());
  std::partial_sort(all.begin(), all.begin() + count, all.end(),
                    [](const auto& a, const auto& b) { return a.error > b.error; });
  const std::vector<Vec3d> corners = singularCorners(finest);
  for (std::size_t i = 0; i < count; ++i) {
    const ExtrapolatedSample& x = all[i];
    const Vec3d d = normalized(x.point - config.reference);
    double nearest = 1e9;
    Vec3d corner{0.0};
    for (const Vec3d& c : corners)
      if (angleBetween(d, c) < nearest) nearest = angleBetween(d, c), corner = c;
    std::string changes;
    for (double c : x.changes) changes += (changes.empty() ? "" : " -> ") + std::to_string(c);
    // The virtual direction the test map shows there (where on the source the content comes from).
    const auto shown = test.toVirtual(x.point - config.reference);
    const Vec3d v = shown ? shown->direction : Vec3d{0.0};
    std::printf("  worst %zu: %s %.4f,%.4f error %.3f px (finest %.3f, uncertainty %.3f), level "
                "changes %s px, local order %.2f; %.2f deg from corner (%.3f, %.3f, %.3f); shows "
                "virtual (%.4f, %.4f, %.4f)\n",
                i + 1, config.walls[x.wall].name.c_str(), x.s, x.t, x.error, x.finestError,
                x.uncertainty, changes.c_str(),
                x.changes.size() >= 2
                    ? richardsonOrder(x.changes[x.changes.size() - 2], x.changes.back())
                    : 0.0,
                nearest * 180 / std::numbers::pi, corner.x, corner.y, corner.z, v.x, v.y, v.z);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"confvis map accuracy benchmark: error against a converged map, kinks, re-bake time"};
  const std::string dir = std::string(CONFVIS_SOURCE_DIR) + "/configs/";
  std::string configs = dir + "cave5.json," + dir + "cave3.json," + dir + "md230x6.json";
  std::string scales = "1,0.5,0.25", routes = "spherical,euclidean,hyperbolic";
  std::string referenceRoute = "spherical";
  std::string cacheDir = std::string(CONFVIS_BINARY_DIR) + "/map_accuracy_cache";
  double referenceStart = 0.125, referenceMin = 0.0625, convergePx = 0.05;
  int samples = 96, lines = 10, repeat = 5, threads = 0;
  std::string gradings = "0";
  TemplateGrading gradingShape, referenceGrading;
  app.add_option("--configs", configs, "Display configs, comma-separated")->capture_default_str();
  app.add_option("--scales", scales, "Edge lengths as multiples of each config's")->capture_default_str();
  app.add_option("--routes", routes, "Routes: spherical, euclidean, hyperbolic")->capture_default_str();
  app.add_option("--reference-route", referenceRoute, "Route of the converged map")->capture_default_str();
  app.add_option("--reference-start", referenceStart, "First reference level (scale)")->capture_default_str();
  app.add_option("--reference-min", referenceMin, "Finest reference level (scale)")->capture_default_str();
  app.add_option("--reference-grading", referenceGrading.radiusDegrees,
                 "Grading radius of the reference, degrees (0: uniform)")->capture_default_str();
  app.add_option("--reference-grading-min", referenceGrading.minScale,
                 "Smallest edge of the reference, x its edge length")->capture_default_str();
  app.add_option("--converge-px", convergePx, "Stop refining the reference below this p99 change")->capture_default_str();
  app.add_option("--cache-dir", cacheDir, "Where reference maps are cached")->capture_default_str();
  app.add_option("--samples", samples, "Error samples per wall side")->capture_default_str();
  app.add_option("--lines", lines, "Kink lines per wall side (x2 directions)")->capture_default_str();
  app.add_option("--gradings", gradings,
                 "Grading radii toward the singular corners, degrees (0: uniform edges)")
      ->capture_default_str();
  app.add_option("--grading-exponent", gradingShape.exponent, "Grading power law exponent")
      ->capture_default_str();
  app.add_option("--grading-min", gradingShape.minScale, "Smallest edge, x the edge length")
      ->capture_default_str();
  app.add_option("--repeat", repeat, "Re-bakes timed per row (median)")->capture_default_str();
  app.add_option("--threads", threads, "Threads (0: one per core)")->capture_default_str();
  std::string interpolations = "linear", referenceInterpolationName = "linear";
  app.add_option("--interpolations", interpolations,
                 "Map interpolations, comma-separated: linear, mobius")->capture_default_str();
  app.add_option("--reference-interpolation", referenceInterpolationName,
                 "Interpolation of the converged map: linear, mobius")->capture_default_str();
  bool extrapolate = false;
  double referenceOrder = 0;
  app.add_flag("--reference-extrapolate", extrapolate,
               "Measure against the Richardson extrapolation of the last two reference levels");
  app.add_option("--reference-order", referenceOrder,
                 "Order of the extrapolation (0: estimated from the p99 changes of the last three "
                 "levels, 2 with only two)")->capture_default_str();
  int worst = 0;
  app.add_option("--worst", worst,
                 "With --reference-extrapolate: print each row's N worst samples (errors, the "
                 "levels' changes there, degrees to the nearest singular corner)")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    const MapInterpolation referenceInterpolation = parseMapInterpolation(referenceInterpolationName);
    for (const std::string& configPath : splitList(configs)) {
      const DisplayConfig config = loadDisplayConfig(configPath);
      std::printf("\n%s (default edge %.3f m, cube %d; px of its walls)\n", config.name.c_str(),
                  config.edgeLength, config.cubeResolution);
      std::fflush(stdout);
      // The converged reference.
      const DisplayMapRoute refRoute = parseRoute(referenceRoute);
      double scale = referenceStart;
      // The last three levels, coarse first (the extrapolation's); the finest is `reference`.
      std::vector<std::unique_ptr<DisplayMap>> levels;
      levels.push_back(std::make_unique<DisplayMap>(referenceMap(
          config, refRoute, referenceRoute, scale * config.edgeLength, referenceGrading, cacheDir)));
      while (scale * 0.5 >= referenceMin * (1 - 1e-9)) {
        scale *= 0.5;
        auto finer = std::make_unique<DisplayMap>(referenceMap(
            config, refRoute, referenceRoute, scale * config.edgeLength, referenceGrading, cacheDir));
        const MapError change = measureMapError(config, *levels.back(), *finer, samples, threads,
                                                referenceInterpolation, referenceInterpolation);
        std::printf("reference %s %.4f m -> %.4f m: change p50 %.3f p95 %.3f p99 %.3f max %.3f px\n",
                    referenceRoute.c_str(), 2 * scale * config.edgeLength,
                    scale * config.edgeLength, change.p50, change.p95, change.p99, change.max);
        std::fflush(stdout);
        levels.push_back(std::move(finer));
        if (levels.size() > 3) levels.erase(levels.begin());
        if (change.p99 < convergePx) break;
      }
      const DisplayMap& reference = *levels.back();
      std::vector<std::unique_ptr<DisplayMapEvaluator>> levelEvaluators;
      std::vector<const DisplayMapEvaluator*> levelViews;
      double order = referenceOrder;
      if (extrapolate) {
        if (levels.size() < 2)
          throw Error(ErrorCode::InvalidInput, "--reference-extrapolate needs two reference levels or more");
        for (const auto& level : levels) {
          levelEvaluators.push_back(std::make_unique<DisplayMapEvaluator>(*level, referenceInterpolation));
          levelViews.push_back(levelEvaluators.back().get());
        }
        const ReferenceConvergence convergence =
            measureReferenceConvergence(config, levelViews, samples, threads);
        if (convergence.changes.size() >= 2)
          std::printf("reference order (last three levels): p50 %.2f p95 %.2f p99 %.2f\n",
                      convergence.orderP50, convergence.orderP95, convergence.orderP99);
        if (order <= 0) order = convergence.changes.size() >= 2 ? convergence.orderP99 : 2.0;
        std::printf("extrapolating the last two levels with order %.2f\n", order);
        std::fflush(stdout);
      }
      std::printf("| edge m | route | interpolation | grading deg | S+T vertices | p50 | p95 | p99 | max px (worst wall s,t) | kink p50 / p95 / p99 / max deg | re-bake ms wall / CPU |%s\n",
                  extrapolate ? " p99 / max vs finest level | reference uncertainty p50 / p99 / max |" : "");
      std::printf("|---|---|---|---|---|---|---|---|---|---|---|%s\n", extrapolate ? "---|---|" : "");
      for (const std::string& s : splitList(scales))
        for (const std::string& routeName : splitList(routes))
          for (const std::string& g : splitList(gradings))
          for (const std::string& interpolationName : splitList(interpolations)) {
          const MapInterpolation interpolation = parseMapInterpolation(interpolationName);
          const double edge = std::stod(s) * config.edgeLength;
          DisplayMapOptions options;
          options.edgeLength = edge;
          options.route = parseRoute(routeName);
          options.grading = gradingShape;
          options.grading.radiusDegrees = std::stod(g);
          std::vector<double> times, cpu;
          DisplayMap map;
          RetargetMap baked;
          BakeOptions bake;
          bake.reference = config.reference;
          bake.threads = threads;
          bake.interpolation = interpolation;
          for (int r = 0; r < std::max(1, repeat); ++r) {
            const auto start = SteadyClock::now();
            const double cpuStart = processCpuSeconds();
            map = computeDisplayMap(config, options);
            bakeRetargetMapInto(map, config.cubeResolution, bake, baked);
            times.push_back(secondsSince(start) * 1e3);
            cpu.push_back((processCpuSeconds() - cpuStart) * 1e3);
          }
          const std::string taken = map.stats["source"]["route"].get<std::string>() + "/" +
                                    map.stats["target"]["route"].get<std::string>();
          MapError e;
          std::string extra;
          if (extrapolate) {
            const DisplayMapEvaluator test(map, interpolation);
            const ExtrapolatedMapError x =
                measureMapErrorExtrapolated(config, test, levelViews, order, samples, threads);
            e = x.error;
            char text[160];
            std::snprintf(text, sizeof text, " %.3f / %.2f | %.3f / %.3f / %.2f |", x.finest.p99,
                          x.finest.max, x.uncertainty.p50, x.uncertainty.p99, x.uncertainty.max);
            extra = text;
            if (worst > 0) printWorstSamples(config, test, levelViews, *levels.back(), order, samples,
                                             threads, worst);
          } else {
            e = measureMapError(config, map, reference, samples, threads, interpolation,
                                referenceInterpolation);
          }
          const KinkStats k = measureKinks(config, map, lines, 10, 0.01, 3, threads, interpolation);
          std::printf("| %.4f | %s%s | %s | %s | %zu+%zu | %.3f | %.3f | %.3f | %.2f (%s %.2f,%.2f) | %.3f / %.3f / %.3f / %.1f | %.1f / %.1f |%s\n",
                      edge, routeName.c_str(),
                      taken == routeName + "/" + routeName ? "" : (" (took " + taken + ")").c_str(),
                      interpolationName.c_str(), g.c_str(), map.source.sphere.size(), map.target.sphere.size(), e.p50, e.p95, e.p99,
                      e.max, e.worstWall.c_str(), e.worstS, e.worstT, k.p50, k.p95, k.p99, k.max, median(times), median(cpu), extra.c_str());
          std::fflush(stdout);
        }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
