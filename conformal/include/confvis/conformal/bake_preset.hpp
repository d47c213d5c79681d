#pragma once
// Bake presets (issue 22, point 4): the accuracy / re-bake time trade of a display map as one
// word. Measured on cave5 against its converged map (conformal/README.md, "Map accuracy",
// "Presets" and "Smooth interpolation"):
//   fast      the config's edge_length, uniform edges, linear interpolation, the Euclidean
//             route on a display without convex boundary corners (cave5, cave6), else the
//             spherical one (presetSettings(preset, config)): the re-bake is meant to fit the 33 ms
//             budget of a tracked head (cave5 at 20 cm: conformal/README.md, "Presets"), but
//             content lands up to ~54 px (p99) / 113 px (max) off near the singular corners, and
//             straight lines kink by ~21 degrees (p99).
//   accurate  half the config's edge_length, graded toward the singular corners (30 degrees,
//             edges down to 1/1024), spherical route, per-vertex Möbius blending
//             (map_interpolation.hpp): cave5 at p99 0.47 px, max 0.6 px against an
//             extrapolated reference resolved near the corners, kinks p99 0.04
//             degrees, for ~13x the CPU of `fast` (~1 s): what offline bakes and renders use.
//             presetSettings(preset, config) takes 0.4 of the edge where the display has a
//             convex boundary corner (cave3: p99 0.90 px at 8 cm against 2.1 px at 10 cm).
// `confvis bake` and `render` default to accurate (baked once, then cached); `view`, `walk` and
// the live map follower (backgroundBake) to fast. BakeDisplayOptions (bake_display.hpp) takes a
// preset and lets route, grading and interpolation be overridden one by one.
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "confvis/base/export.hpp"
#include "confvis/conformal/display_map.hpp"
#include "confvis/conformal/map_interpolation.hpp"
#include "confvis/engine/display_config.hpp"

namespace confvis CONFVIS_API {

enum class BakePreset { Fast, Accurate };

inline constexpr BakePreset kOfflineBakePreset = BakePreset::Accurate;  // bake, render
inline constexpr BakePreset kLiveBakePreset = BakePreset::Fast;         // view, walk, followers

const char* toString(BakePreset preset);
// "fast" or "accurate"; anything else throws Error(InvalidInput) naming the value and the choices.
BakePreset parseBakePreset(std::string_view name);

// What a preset sets: the edge length as a multiple of the config's edge_length (used where no
// edge length is given explicitly), the disk-map route, the grading and how the bake
// interpolates between the mesh vertices.
struct BakePresetSettings {
  double edgeScale = 1;
  DisplayMapRoute route = DisplayMapRoute::Spherical;
  TemplateGrading grading;
  MapInterpolation interpolation = MapInterpolation::Linear;
};
BakePresetSettings presetSettings(BakePreset preset);

// The smallest angle (radians), on the sphere of directions from the config's reference point, at
// a corner of the display's boundary: at each corner of a wall (of surfaceConfig), the angles of
// the walls having it as a corner plus π for each wall having it on an edge; where they add up
// to less than 2π the point is a boundary corner. 2π where there is none. cave5's top corners:
// 4π/3; cave3's open back corners and md230x6's outer corners: below π (convex).
double smallestBoundaryCornerAngle(const DisplayConfig& config);

// The preset's settings for this display. `accurate` takes 0.4 of the config's edge instead of
// 0.5 where the display has a convex boundary corner (smallestBoundaryCornerAngle < π - 0.2):
// there the map to the disk goes like z^(π/β), its inverse has an unbounded derivative, and
// cave3 (corners of 2π/3) measured p99 2.1 px at 0.5 against 0.90 px at 0.4, where cave5 (no
// convex corner) meets its goal at 0.5 (conformal/README.md, "Map accuracy"). `fast` takes the
// Euclidean route (2.5x cheaper flow) where the display has no convex boundary corner: there its
// hole (a vertex's star on the mirror plane) keeps the map mirror-symmetric (cave5: 0.0000 px),
// where cave3's and md230x6's go px to 1000s of px off (conformal/README.md, "Presets").
BakePresetSettings presetSettings(BakePreset preset, const DisplayConfig& config);

// The settings of a display map that the config does not hold (route, grading, interpolation), as
// JSON: part of the bake cache's key and of bake.json ("map_settings"), so that bakes differing
// in any of them never share a cache entry.
nlohmann::json mapSettingsJson(DisplayMapRoute route, const TemplateGrading& grading,
                               MapInterpolation interpolation);

const char* toString(DisplayMapRoute route);
const char* toString(MapInterpolation interpolation);  // "linear" or "mobius"
// "linear" or "mobius"; anything else throws Error(InvalidInput) naming the value and the choices.
MapInterpolation parseMapInterpolation(std::string_view name);

}  // namespace confvis
