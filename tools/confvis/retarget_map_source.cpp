#include "retarget_map_source.hpp"

#include "confvis/backends/retarget_map_files.hpp"
#include "confvis/base/error.hpp"
#include "confvis/conformal/display_template.hpp"
#include "confvis/conformal/bake_display.hpp"
#include "confvis/conformal/bake_verdict.hpp"

namespace confvis::cli {

MapSource retargetMapFor(const DisplayConfig& config, const std::string& mapDirectory,
                         bool showProgress, BakePreset preset,
                         std::optional<MapInterpolation> interpolation) {
  if (!mapDirectory.empty())
    return {readRetargetMapDirectory(mapDirectory), mapDirectory};
  if (displayMapIsIdentity(config)) {
    const Vec3d c{config.reference.x, config.reference.y, config.reference.z};
    return {RetargetMap::identity(config.cubeResolution, c),
            "identity (closed display without bezels)"};
  }
  BakeDisplayOptions options;
  options.showProgress = showProgress;
  options.preset = preset;
  options.interpolation = interpolation;
  BakedDisplay baked = bakeDisplay(config, options);
  std::string origin = baked.fromCache ? "baked earlier" : "baked now";
  if (!baked.cacheEntry.empty()) origin += " (cache " + baked.cacheEntry.string() + ")";
  if (const std::string repair = repairNote(baked.sidecar); !repair.empty())
    origin += ", " + repair;
  return {std::move(baked.map), std::move(origin)};
}

BakeFunction followerBake(int resolution, double edgeLength, BakePreset preset) {
  BakeDisplayOptions options;
  options.preset = preset;
  options.useCache = false;
  if (resolution > 0) options.resolution = resolution;
  if (edgeLength > 0.0) options.edgeLength = edgeLength;
  return [options](const DisplayConfig& config, const glm::dvec3&) {
    return bakeDisplay(config, options).map;
  };
}

}  // namespace confvis::cli
