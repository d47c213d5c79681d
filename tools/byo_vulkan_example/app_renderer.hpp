#pragma once
// The example application's renderer (bring-your-own Vulkan, issue 25): its own Vulkan instance,
// device, render pass and pipelines, drawing a confvis scene on every wall of a display through
// the conformal map with the byo_* helpers of confvis_vulkan (upload, per-wall bounds, the
// conformal pre-pass recorded on its own command buffer). Centre eye, one pass per wall.
#include <functional>
#include <string>
#include <vector>

#include "confvis/backends/render_backend.hpp"
#include "confvis/engine/scene.hpp"

namespace byo_example {

struct AppOptions {
  std::string device = "llvmpipe";  // part of a device name; "" = the first usable device
  bool validation = false;          // Khronos validation layer, messages to onValidationMessage
  std::function<void(const std::string&)> onValidationMessage;
  double resolutionScale = 1.0;     // wall pixels x scale, at least 1
  double errorPixels = 0.5;         // WarpTolerances::errorPixels
  // A deliberately broken render (tests): only the pre-pass's flat list, without the pieces
  // (split at midpoints and along the cut) and the tessellated lists.
  bool onlyFlatList = false;
};

// Renders `scene` on every wall of `config` through `map` (centre eye, camera at rest), one
// image per wall in config order. Throws confvis::Error naming what failed.
std::vector<confvis::WallImage> renderThroughMap(const confvis::DisplayConfig& config,
                                                 const confvis::Scene& scene,
                                                 const confvis::RetargetMap& map,
                                                 const AppOptions& options);

}  // namespace byo_example
