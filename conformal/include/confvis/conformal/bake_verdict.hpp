#pragma once
// Whether a baked map is fit to use (never a silently broken map): the disk maps keep every
// triangle's orientation, the image of the display covers the source field, and the map has no
// conformality outliers. bakeDisplay (bake_display.hpp) repairs a bake that fails (finer edges, a
// hemisphere source) or refuses it with an Error naming the cause and the fix.
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "confvis/base/export.hpp"
#include "confvis/conformal/display_map.hpp"
#include "confvis/conformal/retarget_map.hpp"

namespace confvis CONFVIS_API {

// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
struct BakeVerdict {
  std::size_t flippedTriangles = 0;  // source and target disk triangles turned over (or flat)
  std::size_t flippedTexels = 0;     // ray texels whose Jacobian reverses orientation
  // Source directions shown on the display, lit or on a bezel (bezels are covered but unlit by
  // design), over all source directions: 1 for a bijection.
  double coverage = 1;
  double ratioP99 = 1;  // ray's singular-value ratio (1 = conformal), 99th percentile
  std::vector<std::string> problems;  // empty: fit to use
  bool ok() const { return problems.empty(); }
  std::string summary() const;  // the problems joined, or "no problems"
  nlohmann::json toJson() const;
};

// Conformality outliers: a p99 ratio above kMaxRatioP99. Correct maps measure 1.3-2.6 (flat-wall
// 1.35, md230x6 1.27, cave5 2.49, cave3 2.51, cave4 2.57 at their shipped settings); the 4-monitor
// desktop rig of issue 22 (configs/imported/sgct-desktop4.json) 1.9e4 with a sphere source and
// 6.5e5 with a hemisphere one at 20 cm.
inline constexpr double kMaxRatioP99 = 4.0;
inline constexpr double kMinCoverage = 0.995;

// Measures ray at stride max(1, n / 128), as bake.json does.
BakeVerdict judgeBake(const DisplayMap& displayMap, const RetargetMap& map);

// The repair a bake.json records (timings.display_map.repair), as one line for the user:
// "repaired with <attempt> after <first attempt's problems>"; empty when none was needed.
std::string repairNote(const nlohmann::json& sidecar);

}  // namespace confvis
