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
  // How the application stores its vertices in its own vertex buffer (VertexLayout):
  // Float32: uv R32G32, position and normal R32G32B32, 36 bytes, uint32 indices;
  // Half: position and normal R16G16B16A16_SFLOAT, uv R16G16_SFLOAT, 24 bytes, uint16 indices;
  // Mixed: position R32G32B32A32_SFLOAT, normal R16G16B16A16_SFLOAT, uv R16G16_UNORM, 32 bytes.
  enum class VertexFormat { Float32, Half, Mixed };
  VertexFormat vertexFormat = VertexFormat::Float32;
  // A deliberately wrong layout (tests): the pre-pass is told the positions lie at the normals'
  // offset. (A wrong stride fails as surely, but scatters triangles across the whole scene,
  // which costs lavapipe minutes to tessellate.)
  bool wrongPositionOffset = false;
  // The map uploaded on the frame's own command buffer (recordRetargetMapUpload), in the same
  // submission as the pre-pass, instead of by uploadRetargetMap's own submission.
  bool recordedUpload = false;
};

// Renders `scene` on every wall of `config` through `map` (centre eye, camera at rest), one
// image per wall in config order. Throws confvis::Error naming what failed.
std::vector<confvis::WallImage> renderThroughMap(const confvis::DisplayConfig& config,
                                                 const confvis::Scene& scene,
                                                 const confvis::RetargetMap& map,
                                                 const AppOptions& options);

}  // namespace byo_example
