// confvis bake: from a display config to the two direction cube maps (ray.exr, geom.exr), their
// sidecar, meshes and previews (conformal/bake_files.hpp), through the on-disk bake cache.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "command.hpp"
#include "preset_option.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/file_checks.hpp"
#include "confvis/base/input_limits.hpp"
#include "confvis/conformal/bake_display.hpp"
#include "confvis/conformal/bake_verdict.hpp"
#include "confvis/conformal/bake_files.hpp"

namespace confvis::cli {
namespace {

namespace fs = std::filesystem;

struct BakeArgs {
  std::string config, output, cacheDir, preset, interpolation;
  std::vector<double> reference;  // x, y, z when given
  int resolution = 0;
  double edgeLength = 0;
  int threads = 0;
  bool noCache = false, quiet = false;
};

double seconds(const nlohmann::json& json, const char* key) {
  return json.contains(key) && json[key].is_number() ? json[key].get<double>() : 0.0;
}

void printSummary(const BakedDisplay& baked, const fs::path& output) {
  const nlohmann::json& s = baked.sidecar;
  const nlohmann::json& quality = s["quality"];
  const int n = baked.map.resolution();
  if (baked.fromCache) {
    std::printf("%s: %dx%d per face from the cache (%s)\n", baked.config.name.c_str(), n, n,
                baked.cacheEntry.string().c_str());
  } else {
    const nlohmann::json& stages = s["timings"]["display_map"];
    std::printf("%s: %dx%d per face; template %.3f s, flow %.3f s, alignment %.3f s, bake %.3f s\n",
                baked.config.name.c_str(), n, n, seconds(stages, "template"),
                seconds(stages, "flow"), seconds(stages, "alignment"), baked.timings.total);
  }
  const auto& ray = quality["ray_conformality"];
  const auto& roundTrip = quality["round_trip_ray_then_geom"];
  std::printf("  ray conformality (singular-value ratio) p50 %.4f p95 %.4f max %.3f, %d flipped; "
              "round trip max %.3f texels inside, %.2f%% below one at the cut (max %.2f of the "
              "lookup's footprint); coverage %.2f%%\n",
              ray["ratio_p50"].get<double>(), ray["ratio_p95"].get<double>(),
              ray["ratio_max"].get<double>(), ray["flipped_texels"].get<int>(),
              roundTrip["interior"]["error_max_texels"].get<double>(),
              100.0 * roundTrip["boundary"]["fraction_below_one_texel"].get<double>(),
              roundTrip["all"]["error_max_in_footprints"].get<double>(),
              100.0 * quality["coverage"]["fraction"].get<double>());
  std::printf("  -> %s/{ray.exr, geom.exr, bake.json, source.obj, target.obj, *.png}\n",
              output.string().c_str());
}

int runBake(const BakeArgs& args) {
  const DisplayConfig config = loadDisplayConfig(args.config);
  BakeDisplayOptions options;
  if (args.resolution > 0) options.resolution = args.resolution;
  if (args.edgeLength > 0) options.edgeLength = args.edgeLength;
  if (args.reference.size() == 3)
    options.reference = Vec3d{args.reference[0], args.reference[1], args.reference[2]};
  options.useCache = !args.noCache;
  options.cacheDirectory = args.cacheDir;
  options.threads = args.threads;
  options.showProgress = !args.quiet;
  options.preset = parseBakePreset(args.preset);
  options.interpolation = interpolationOverride(args.interpolation);

  const BakedDisplay baked = bakeDisplay(config, options);
  if (!baked.cacheNote.empty()) std::fprintf(stderr, "confvis bake: note: %s\n", baked.cacheNote.c_str());
  if (const std::string repair = repairNote(baked.sidecar); !repair.empty())
    std::fprintf(stderr, "confvis bake: note: %s\n", repair.c_str());
  const fs::path output = args.output.empty()
                              ? childPath({}, baked.config.name + "-bake", "display name")
                              : fs::path(args.output);
  if (!baked.cacheEntry.empty() && pathExists(baked.cacheEntry / "bake.json"))
    copyBakeDirectory(baked.cacheEntry, output);
  else  // no cache, or it could not be written: the files come from memory
    writeBakeDirectory(output, *baked.displayMap, baked.map, baked.sidecar, args.threads,
                       !args.quiet);
  printSummary(baked, output);
  return 0;
}

const RegisterCommand registration{Command{
    "bake", "Bake a display config into ray/geom direction cube maps (OpenEXR) with previews",
    [](CLI::App& sub) {
      auto args = std::make_shared<BakeArgs>();
      sub.add_option("config", args->config, "Display config (JSON, see configs/README.md)")
          ->required();
      sub.add_option("-o,--output", args->output,
                     "Output directory (default: NAME-bake, NAME from the config)");
      sub.add_option("--resolution", args->resolution,
                     "Cube-map face size in texels (default: the config's cube_resolution)")
          ->check(CLI::Range(8, 8192));
      sub.add_option("--edge-length", args->edgeLength,
                     "Template refinement edge length in metres (default: the config's)")
          ->check(kPositiveNumber);
      sub.add_option("--reference", args->reference,
                     "Reference point x,y,z in metres (default: the config's)")
          ->delimiter(',')
          ->expected(3);
      addPresetOption(sub, args->preset, kOfflineBakePreset);
      addInterpolationOption(sub, args->interpolation);
      sub.add_flag("--no-cache", args->noCache, "Neither read nor write the bake cache");
      sub.add_option("--cache-dir", args->cacheDir,
                     "Bake cache directory (default: $CONFVIS_CACHE_DIR, $XDG_CACHE_HOME/confvis "
                     "or ~/.cache/confvis)");
      sub.add_option("--threads", args->threads, "Worker threads (default: one per core)")
          ->check(CLI::NonNegativeNumber);
      sub.add_flag("-q,--quiet", args->quiet, "No progress output");
      return [args] { return runBake(*args); };
    }}};

}  // namespace
}  // namespace confvis::cli
