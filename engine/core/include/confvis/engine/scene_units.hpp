#pragma once
// Scene files carry no unit: confvis takes metres. CAD and photogrammetry models often come in
// millimetres, and then the display sits inside one tiny part of a kilometre-sized model.
#include <optional>
#include <string>

#include "confvis/base/export.hpp"
#include "confvis/engine/display_config.hpp"
#include "confvis/engine/scene.hpp"

namespace confvis CONFVIS_API {

// A scene more than this many times the display's size gets a hint.
inline constexpr double kSceneUnitsHintRatio = 100.0;

// The display's extent: the diagonal of the box around its walls' corners, metres.
double displayExtent(const DisplayConfig& display);

// When the scene's bounding-box diagonal exceeds kSceneUnitsHintRatio times the display's, a
// one-line hint naming both sizes and the --scene-scale factor that would make it metres from
// millimetres; nullopt otherwise (and for an empty scene).
std::optional<std::string> sceneUnitsHint(const Scene& scene, const DisplayConfig& display);

// Multiplies every position by `factor` (> 0, finite; Error(InvalidInput) otherwise).
void scaleScene(Scene& scene, double factor);

}  // namespace confvis
