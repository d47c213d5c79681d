#include "confvis/conformal/bake_display.hpp"

#include <cmath>

#include "bake_cache.hpp"
#include "confvis/base/error.hpp"
#include "confvis/conformal/bake_files.hpp"

namespace confvis {

DisplayConfig effectiveBakeConfig(const DisplayConfig& config, const BakeDisplayOptions& options) {
  nlohmann::json json = toJson(config);
  std::string source = "display config '" + config.name + "'";
  if (options.resolution) json["cube_resolution"] = *options.resolution;
  if (options.edgeLength) json["edge_length"] = *options.edgeLength;
  const double presetScale = presetSettings(options.preset, config).edgeScale;
  if (!options.edgeLength && presetScale != 1) json["edge_length"] = config.edgeLength * presetScale;
  if (options.reference) {
    const Vec3d& r = *options.reference;
    if (!isFinite(r)) throw Error(ErrorCode::InvalidInput, "reference point override is not finite");
    json["reference"] = {r.x, r.y, r.z};
  }
  if (options.resolution || options.edgeLength || options.reference)
    source += " with the command-line overrides";
  // Parsing the canonical form again validates the overrides like the file's own values and
  // recomputes the hash over every field: the cache key of exactly this bake.
  return parseDisplayConfig(json, source);
}

DisplayMapOptions bakeMapOptions(const DisplayConfig& config, const BakeDisplayOptions& options) {
  const BakePresetSettings preset = presetSettings(options.preset, config);
  DisplayMapOptions map;
  map.route = options.route.value_or(preset.route);
  map.grading = options.grading.value_or(preset.grading);
  map.showProgress = options.showProgress;
  return map;
}

MapInterpolation bakeInterpolation(const BakeDisplayOptions& options) {
  return options.interpolation.value_or(presetSettings(options.preset).interpolation);
}

nlohmann::json bakeMapSettings(const DisplayConfig& config, const BakeDisplayOptions& options) {
  const DisplayMapOptions map = bakeMapOptions(config, options);
  return mapSettingsJson(map.route, map.grading, bakeInterpolation(options));
}

BakeOptions displayBakeOptions(const DisplayConfig& config, const BakeDisplayOptions& options) {
  BakeOptions bake;
  bake.reference = {config.reference.x, config.reference.y, config.reference.z};
  bake.threads = options.threads;
  bake.showProgress = options.showProgress;
  bake.interpolation = bakeInterpolation(options);
  return bake;
}

namespace {

// Whether a source's bake holds the texels bakeRetargetMap(map, resolution, wanted) would.
bool sameTexels(const PrebakedRetargetMap& baked, int resolution, const BakeOptions& wanted) {
  return baked.map.resolution() == resolution && baked.map.reference == wanted.reference &&
         baked.options.reference == wanted.reference &&
         baked.options.interpolation == wanted.interpolation;
}

}  // namespace

BakedDisplay bakeDisplayWith(const DisplayConfig& config, const BakeDisplayOptions& options,
                             const DisplayMapSource& computeMap) {
  BakedDisplay result;
  result.config = effectiveBakeConfig(config, options);
  const nlohmann::json mapSettings = bakeMapSettings(result.config, options);
  if (options.useCache) {
    const std::filesystem::path directory =
        options.cacheDirectory.empty() ? defaultCacheDirectory() : options.cacheDirectory;
    result.cacheEntry = bakeCacheEntry(directory, result.config, mapSettings);
    if (auto loaded = detail::loadCacheEntry(result.cacheEntry, result.config, mapSettings,
                                             result.cacheNote)) {
      result.map = std::move(loaded->map);
      result.sidecar = std::move(loaded->sidecar);
      result.fromCache = true;
      return result;
    }
  }
  SourcedDisplayMap sourced = computeMap(result.config);
  DisplayMap& displayMap = sourced.map;
  const BakeOptions bake = displayBakeOptions(result.config, options);
  if (sourced.baked && sameTexels(*sourced.baked, result.config.cubeResolution, bake)) {
    result.map = std::move(sourced.baked->map);
    result.timings = sourced.baked->timings;
  } else {
    result.map = bakeRetargetMap(displayMap, result.config.cubeResolution, bake, &result.timings);
  }
  result.sidecar = makeBakeSidecar(result.config, displayMap, result.map, result.timings, 0,
                                   options.showProgress);
  result.sidecar["map_settings"] = mapSettings;
  if (options.useCache) {
    // A cache that cannot be written (read-only, full disk) costs the next call a bake, no more.
    try {
      result.sidecar = detail::publishCacheEntry(result.cacheEntry, displayMap, result.map,
                                                 result.sidecar, options.threads,
                                                 options.showProgress);
    } catch (const Error& e) {
      result.cacheNote = std::string("cache entry not written: ") + e.what();
    }
  }
  result.displayMap = std::move(displayMap);
  return result;
}

}  // namespace confvis
