#pragma once
// Where `confvis render` gets the conformal map of a display from.
#include <optional>
#include <string>

#include "confvis/conformal/bake_preset.hpp"
#include "confvis/conformal/retarget_map.hpp"
#include "confvis/engine/display_config.hpp"
#include "confvis/runtime/map_follower.hpp"

namespace confvis::cli {

struct MapSource {
  RetargetMap map;
  std::string origin;  // for the report: "identity (closed display without bezels)" or a path
};

// In order: --map DIR (a baked directory: bake.json, ray.exr, geom.exr); the identity for a display
// whose map is the identity (displayMapIsIdentity); otherwise bakeDisplay (through the on-disk cache, so only the
// first render of a display pays for the bake).
// `interpolation` overrides the preset's.
MapSource retargetMapFor(const DisplayConfig& config, const std::string& mapDirectory,
                         bool showProgress, BakePreset preset,
                         std::optional<MapInterpolation> interpolation = std::nullopt);

// The bake a MapFollower re-bakes with as the head moves: bakeDisplay without the on-disk cache
// (every head position is a new config: the cache would only fill up). resolution, edgeLength:
// the config's where 0.
BakeFunction followerBake(int resolution, double edgeLength, BakePreset preset);

}  // namespace confvis::cli
