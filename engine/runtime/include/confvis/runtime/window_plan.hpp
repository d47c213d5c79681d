#pragma once
// Which windows a live display opens and what each shows: one window per wall, its eyes laid
// out as the wall's stereo_output says, placed where its `window` says or tiled on the desktop.
// Pure layout (no window system), so it is tested without a display.
#include <optional>
#include <string>
#include <vector>

#include "confvis/base/export.hpp"
#include "confvis/engine/display_config.hpp"
#include "confvis/engine/viewer.hpp"

namespace confvis CONFVIS_API {

// A monitor as the window system reports it (GLFW: name, position, current video mode and the
// work area left by panels).
struct MonitorInfo {
  std::string name;
  int x = 0, y = 0, width = 0, height = 0;          // the whole screen
  int workX = 0, workY = 0, workWidth = 0, workHeight = 0;  // without panels
};

// One eye's image placed in a window's content, content pixels.
struct EyeRegion {
  Eye eye = Eye::Center;
  int x = 0, y = 0, width = 0, height = 0;
};

struct WindowPlan {
  std::string wall;
  StereoOutput stereo = StereoOutput::Mono;  // resolved: the wall's, or the run's default
  std::vector<Eye> eyes;                     // the distinct eyes rendered for this wall
  std::vector<EyeRegion> regions;            // where each eye's image goes
  int contentWidth = 0, contentHeight = 0;   // pixels the renderer fills
  // Placement on the desktop, screen coordinates; the content is stretched to the window.
  int x = 0, y = 0, width = 0, height = 0;
  bool decorated = true;
  int fullscreenMonitor = -1;  // index into the monitors, or -1 for a window
};

// `stereoRun`: the run renders left and right eyes (confvis view --eyes stereo); walls without a
// stereo_output then show side by side, and "mono" walls the centre eye. A mono run shows the
// centre eye everywhere (twice where the layout has two halves). `scale` sizes the rendered
// images (wall resolution * scale, at least 1 pixel, as RenderSettings::resolutionScale).
// Windows without a position are tiled left to right over the first monitor's work area,
// shrunk together to fit it. Throws Error(InvalidInput) naming the wall for a window on no
// monitor, or a fullscreen monitor that does not exist (listing the monitors).
std::vector<WindowPlan> planWindows(const DisplayConfig& config, bool stereoRun, double scale,
                                    const std::vector<MonitorInfo>& monitors);

// Pixels of one rendered wall image: round(resolution * scale), at least 1 (what the backends
// render for RenderSettings::resolutionScale).
int scaledPixels(int pixels, double scale);

}  // namespace confvis
