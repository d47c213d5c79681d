#pragma once
// What a render call will produce, checked before any work starts; shared by the backends so
// they validate settings the same way and return images in the same order.
#include <optional>
#include <vector>

#include "confvis/backends/render_backend.hpp"
#include "confvis/base/export.hpp"
#include "confvis/engine/view.hpp"

namespace confvis CONFVIS_API {

struct PlannedImage {
  int wallIndex = 0;  // into config.walls
  Eye eye = Eye::Center;
  WallView view;      // off-axis view of the wall for this eye (points into config.walls)
  // RenderSettings::views' override of this wall's eye, if any (`view` is then the off-axis
  // view from the override's eye, for the wall's geometry; the rays are the override's).
  std::optional<ViewOverride> custom;
  int width = 0, height = 0;  // output pixels: round(wall resolution * scale), at least 1
};

// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
struct RenderPlan {
  std::vector<PlannedImage> images;  // walls in settings order, each with its eyes in order
  bool hasOffCentreEyes = false;     // some eye is not at the reference point
};

// Throws Error(InvalidInput) naming the culprit: an unknown wall (listing the known ones), a
// repeated wall or eye, no eyes, samples per pixel outside 1..4096, a non-positive or
// non-finite scale, a missing map in conformal mode, a map baked around another reference point
// than the config's, an eye on or behind a wall.
RenderPlan planRender(const DisplayConfig& config, const RetargetMap* map,
                      const RenderSettings& settings);

// Names used in files and reports: "left", "center", "right"; "plain", "conformal";
// "exact", "fast".
const char* eyeName(Eye eye) noexcept;
const char* modeName(RenderMode mode) noexcept;
const char* stereoRaysName(StereoRays rays) noexcept;

}  // namespace confvis
