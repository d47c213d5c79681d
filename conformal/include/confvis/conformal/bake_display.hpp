#pragma once
// From a display config to its baked RetargetMap in one call, with an on-disk cache: what the
// renderers, `confvis bake` and the public API use.
//
//   config -> effective config (overrides applied, validated, hashed) -> cache lookup ->
//   on a miss: computeDisplayMap -> bakeRetargetMap (once: the checks' bake is the one returned)
//   -> bake directory written into the cache.
//
// The cache key is the effective config's hash (DisplayConfig::hash covers every field,
// resolution, edge length and reference point included) plus a digest of the map settings the
// config does not hold (route, grading, interpolation: mapSettingsJson, bake_preset.hpp), under
// a folder named for the bake format and confvis version, so overrides, presets, format changes
// and new releases never hit stale entries. An entry is a bake directory (bake_files.hpp),
// written into a temporary folder and renamed into place; one that does not load back
// (truncated EXR, sidecar that does not match) is removed and rebuilt. Maps that follow a tracked
// head (a new reference point every few centimetres) are better baked with useCache = false:
// each reference point is a new entry.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "confvis/base/export.hpp"
#include "confvis/conformal/bake.hpp"
#include "confvis/conformal/bake_preset.hpp"
#include "confvis/conformal/display_map.hpp"
#include "confvis/engine/display_config.hpp"

namespace confvis CONFVIS_API {

// Thread-safety: a value (options): read it from any number of threads at once.
struct BakeDisplayOptions {
  std::optional<int> resolution;      // texels per face; default: config.cubeResolution
  std::optional<double> edgeLength;   // metres; default: config.edgeLength
  std::optional<glm::dvec3> reference;     // default: config.reference
  // The accuracy / speed trade (bake_preset.hpp). The API's default is the live one (fast: what a
  // map follower re-bakes with); `confvis bake` and `render` ask for accurate. Without an
  // explicit edgeLength the preset scales the config's edge_length (accurate: half, 0.4 on a display
  // with convex boundary corners: presetSettings(preset, config)).
  BakePreset preset = kLiveBakePreset;
  std::optional<DisplayMapRoute> route;    // default: the preset's for the display
  std::optional<TemplateGrading> grading;  // default: the preset's
  std::optional<MapInterpolation> interpolation;  // default: the preset's
  bool useCache = true;
  std::filesystem::path cacheDirectory;  // empty: defaultCacheDirectory()
  int threads = 0;                       // 0: one per hardware thread
  bool showProgress = false;
};

// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
struct BakedDisplay {
  DisplayConfig config;  // the effective config the map was baked for
  RetargetMap map;
  nlohmann::json sidecar;              // bake.json's contents
  std::optional<DisplayMap> displayMap;  // set when computed by this call (not on a cache hit)
  BakeTimings timings;                 // of this call's bake (zero on a cache hit)
  std::filesystem::path cacheEntry;    // the bake directory in the cache; empty without cache
  bool fromCache = false;
  std::string cacheNote;  // why an existing entry was rebuilt (corrupt, partial), else empty
};

// CONFVIS_CACHE_DIR if set, else $XDG_CACHE_HOME/confvis, else $HOME/.cache/confvis, else
// <temp>/confvis-cache.
std::filesystem::path defaultCacheDirectory();

// The config with the options' overrides applied (the preset's edge scale where no edge length is
// given), validated again (e.g. a reference point outside the display) and re-hashed. Throws
// Error(InvalidInput) naming the override.
DisplayConfig effectiveBakeConfig(const DisplayConfig& config, const BakeDisplayOptions& options);

// The route and grading a bake of this (effective) config with these options uses (the preset's
// for this display, presetSettings(preset, config), unless overridden).
DisplayMapOptions bakeMapOptions(const DisplayConfig& effectiveConfig,
                                 const BakeDisplayOptions& options);
// How it interpolates between the mesh vertices (the preset's unless overridden).
MapInterpolation bakeInterpolation(const BakeDisplayOptions& options);
// The BakeOptions of a bake of the effective config with these options (its reference point,
// the interpolation above, threads and progress).
BakeOptions displayBakeOptions(const DisplayConfig& effectiveConfig,
                               const BakeDisplayOptions& options);
// mapSettingsJson of both.
nlohmann::json bakeMapSettings(const DisplayConfig& effectiveConfig,
                               const BakeDisplayOptions& options);

// Where the cache keeps the bake of an effective config with these map settings
// (bakeMapSettings).
std::filesystem::path bakeCacheEntry(const std::filesystem::path& cacheDirectory,
                                     const DisplayConfig& effectiveConfig,
                                     const nlohmann::json& mapSettings);

// computeDisplayMap (templates, flows, alignment) and bakeRetargetMap, through the cache.
BakedDisplay bakeDisplay(const DisplayConfig& config, const BakeDisplayOptions& options = {});

// A RetargetMap a DisplayMapSource has already baked (bakeDisplay's checks bake each candidate
// map to judge it), with the options it was baked with.
// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
struct PrebakedRetargetMap {
  RetargetMap map;
  BakeOptions options;
  BakeTimings timings;
};

// What a DisplayMapSource hands back: the display map and, optionally, its bake. bakeDisplayWith
// returns that bake instead of baking the same map again when it was made with the resolution,
// reference point and interpolation bakeDisplayWith would bake with (threads and progress do not
// change the texels); otherwise it bakes the map itself.
// Thread-safety: a value, as PrebakedRetargetMap.
struct SourcedDisplayMap {
  SourcedDisplayMap() = default;
  // A source of display maps alone (no bake to reuse) converts implicitly.
  SourcedDisplayMap(DisplayMap displayMap) : map(std::move(displayMap)) {}  // NOLINT
  DisplayMap map;
  std::optional<PrebakedRetargetMap> baked;
};

// The same with another source of DisplayMaps (tests, custom templates).
using DisplayMapSource = std::function<SourcedDisplayMap(const DisplayConfig& effectiveConfig)>;
BakedDisplay bakeDisplayWith(const DisplayConfig& config, const BakeDisplayOptions& options,
                             const DisplayMapSource& computeMap);

}  // namespace confvis
