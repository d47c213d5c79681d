// Bake presets (bake_preset.hpp).
#include "confvis/conformal/bake_preset.hpp"

#include <string>

#include "confvis/base/error.hpp"

namespace confvis {

const char* toString(BakePreset preset) {
  return preset == BakePreset::Fast ? "fast" : "accurate";
}

BakePreset parseBakePreset(std::string_view name) {
  if (name == "fast") return BakePreset::Fast;
  if (name == "accurate") return BakePreset::Accurate;
  throw Error(ErrorCode::InvalidInput,
              "unknown bake preset '" + std::string(name) + "' (choose fast or accurate)");
}

BakePresetSettings presetSettings(BakePreset preset) {
  BakePresetSettings settings;
  if (preset == BakePreset::Fast) return settings;  // the config's edges, uniform, spherical
  // Measured on cave5 (conformal/README.md, "Presets" and "Smooth interpolation"): halving the
  // edges takes the bulk of the error (p50) down 4x; grading around the singular corners down to
  // 1/64 of the edge takes the tail (p99 15 -> 0.87 px, max 80 -> 1.3 px at 10 cm, 20 degrees);
  // Möbius blending takes the kinks from first order to ~0 (p99 3.7 -> 0.04 degrees) and the
  // error further down: 30 degrees with Möbius blending is the first setting measured within
  // issue 22's goals (p99 0.43 px, max 0.97 px; 20 degrees: p99 0.56 px).
  settings.edgeScale = 0.5;
  settings.grading.radiusDegrees = 30;
  settings.grading.minScale = 1.0 / 64;
  settings.interpolation = MapInterpolation::Mobius;
  return settings;
}

const char* toString(DisplayMapRoute route) {
  switch (route) {
    case DisplayMapRoute::Spherical: return "spherical";
    case DisplayMapRoute::Euclidean: return "euclidean";
    case DisplayMapRoute::Hyperbolic: return "hyperbolic";
  }
  return "?";
}

const char* toString(MapInterpolation interpolation) {
  return interpolation == MapInterpolation::Mobius ? "mobius" : "linear";
}

MapInterpolation parseMapInterpolation(std::string_view name) {
  if (name == "linear") return MapInterpolation::Linear;
  if (name == "mobius") return MapInterpolation::Mobius;
  throw Error(ErrorCode::InvalidInput,
              "unknown map interpolation '" + std::string(name) + "' (choose linear or mobius)");
}

nlohmann::json mapSettingsJson(DisplayMapRoute route, const TemplateGrading& grading,
                               MapInterpolation interpolation) {
  nlohmann::json json = {{"route", toString(route)}, {"interpolation", toString(interpolation)}};
  if (grading.radiusDegrees > 0)
    json["grading"] = {{"radius_degrees", grading.radiusDegrees},
                       {"exponent", grading.exponent},
                       {"min_scale", grading.minScale}};
  else
    json["grading"] = "uniform";
  return json;
}

}  // namespace confvis
