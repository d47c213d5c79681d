// Bake presets (bake_preset.hpp).
#include "confvis/conformal/bake_preset.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "confvis/base/error.hpp"
#include "confvis/engine/display_surfaces.hpp"

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
  if (preset == BakePreset::Fast) return settings;  // the config's edges, uniform (route: below)
  // Measured on cave5 (conformal/README.md, "Presets" and "Smooth interpolation"): halving the
  // edges takes the bulk of the error (p50) down 4x; grading around the singular corners down to
  // 1/64 of the edge takes the tail (p99 15 -> 0.87 px, max 80 -> 1.3 px at 10 cm, 20 degrees);
  // Möbius blending takes the kinks from first order to ~0 (p99 3.7 -> 0.04 degrees) and the
  // error further down: 30 degrees with Möbius blending is the first setting measured within
  // issue 22's goals (p99 0.43 px, max 0.97 px; 20 degrees: p99 0.56 px). The floor of 1/1024
  // (not 1/64) takes cave5's max from 3.8-5.4 px to 0.6 px against a reference resolved there
  // (conformal/README.md, "cave5's max"): the worst content sits on the top edges next to the
  // images of the cut's centres and comes from virtual directions next to the cut leaves.
  settings.edgeScale = 0.5;
  settings.grading.radiusDegrees = 30;
  settings.grading.minScale = 1.0 / 1024;
  settings.interpolation = MapInterpolation::Mobius;
  return settings;
}

namespace {

constexpr double kPi = std::numbers::pi;

// The angle at corner k of `wall` on the sphere of directions from c: between the great circles
// towards its two neighbouring corners.
double sphericalCornerAngle(const std::array<Vec3d, 4>& corners, int k, const Vec3d& c) {
  const Vec3d p = normalized(corners[k] - c);
  auto tangent = [&](int j) {
    const Vec3d q = normalized(corners[j] - c);
    return q - dot(q, p) * p;
  };
  return angleBetween(tangent((k + 1) % 4), tangent((k + 3) % 4));
}

// What `wall` adds to the angle around point x: its corner angle, π on an edge, 2π inside, 0 off.
double angleAround(const Wall& wall, const Vec3d& x, const Vec3d& c, double tolerance) {
  const auto corners = wall.corners();
  for (int k = 0; k < 4; ++k)
    if (norm(corners[k] - x) < tolerance) return sphericalCornerAngle(corners, k, c);
  const Vec3d d = x - wall.lowerLeft;
  if (std::abs(dot(d, wall.normal())) > tolerance) return 0;
  const double width = wall.widthMetres(), height = wall.heightMetres();
  const double s = dot(d, wall.right()) / width, t = dot(d, wall.up()) / height;
  const double ts = tolerance / width, tt = tolerance / height;
  if (s < -ts || s > 1 + ts || t < -tt || t > 1 + tt) return 0;
  const bool onEdge = s < ts || s > 1 - ts || t < tt || t > 1 - tt;
  return onEdge ? kPi : 2 * kPi;
}

}  // namespace

double smallestBoundaryCornerAngle(const DisplayConfig& config) {
  const DisplayConfig surfaces = surfaceConfig(config);
  double smallest = 2 * kPi;
  for (const Wall& wall : surfaces.walls)
    for (const Vec3d& x : wall.corners()) {
      const double tolerance = 1e-6 * std::max(1.0, norm(x - config.reference));
      double around = 0;
      for (const Wall& other : surfaces.walls)
        around += angleAround(other, x, config.reference, tolerance);
      if (around < 2 * kPi - 1e-9) smallest = std::min(smallest, around);
    }
  return smallest;
}

BakePresetSettings presetSettings(BakePreset preset, const DisplayConfig& config) {
  BakePresetSettings settings = presetSettings(preset);
  const bool convexCorner = smallestBoundaryCornerAngle(config) < kPi - 0.2;
  if (preset == BakePreset::Accurate && convexCorner) settings.edgeScale = 0.4;
  // The Euclidean route's flow costs 2.5x less than the spherical one's (cave5 at 20 cm: 9 against
  // 23 ms, the re-bake's budget is 33), but its hole can bend the map: mirror asymmetry of the
  // fast bake (tools/bench/alignment_bench.cpp --route euclidean, max px) with the vertex-star
  // hole: cave5 and cave6 0.0000, where displays with convex boundary corners go off (cave3
  // left/right 9.1, md230x6 top/bottom 2941; with the earlier one-face hole cave4 12, flat-wall
  // 541; spherical: <= 0.02 on all). conformal/README.md, "Presets".
  if (preset == BakePreset::Fast && !convexCorner) settings.route = DisplayMapRoute::Euclidean;
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
