#pragma once
// Navigation in the virtual world from any of the display's windows: WASD moves the virtual
// camera on the ground plane (Q / E down and up), dragging with the left mouse button turns it
// (yaw, pitch), as `confvis render --camera` places it.
#include <memory>
#include <vector>

#include "confvis/backends/render_backend.hpp"
#include "confvis/base/export.hpp"
#include "confvis/runtime/display_window.hpp"

namespace confvis CONFVIS_API {

// Thread-safety: not thread-safe; call it from the thread that polls the windows' events.
class CameraControls {
 public:
  double metresPerSecond = 1.5;
  double degreesPerPixel = 0.2;
  // Applies the keys held and the mouse dragged since the last call, `seconds` after it.
  void update(const std::vector<std::unique_ptr<DisplayWindow>>& windows, VirtualCamera& camera,
              double seconds);

 private:
  const DisplayWindow* dragged_ = nullptr;
  double lastX_ = 0.0, lastY_ = 0.0;
};

}  // namespace confvis
