#pragma once
// The frame loop of a live display (`confvis view`): every frame polls the windows and the
// tracker, takes the follower's current map (never waiting for a re-bake), renders every wall
// for every eye its window shows, and presents each window through its swapchain. Ends after
// `frames` frames, on Esc, or when a window is closed; returns the report for view.json.
#include <filesystem>

#include <nlohmann/json.hpp>

#include "confvis/backends/render_backend.hpp"
#include "confvis/base/export.hpp"
#include "confvis/runtime/map_follower.hpp"
#include "confvis/runtime/tracker.hpp"

namespace confvis CONFVIS_API {

struct LiveViewOptions {
  bool stereo = false;   // render left and right eyes (walls show them per stereo_output)
  StereoRays stereoRays = StereoRays::Exact;  // conformal stereo eyes (RenderSettings')
  bool vsync = true;     // FIFO; false: MAILBOX or IMMEDIATE where offered
  int frames = 0;        // 0: until Esc or a window is closed
  double scale = 1.0;    // rendered pixels per wall pixel
  RenderMode mode = RenderMode::Conformal;  // C toggles
  VirtualCamera camera;  // where the display's reference point starts in the scene
  // Each window's last presented frame, read back from its swapchain image, as DIR/WALL.png.
  std::filesystem::path screenshotDirectory;
  bool validation = false;  // Khronos validation on the presenting device, counted in the report
  bool showProgress = true; // a status line on stderr about once a second
};

// `tracker` may be null (the head stays at the display's reference point). Throws Error naming
// the wall for window placement errors, and the backend's errors naming the frame.
nlohmann::json runLiveView(const DisplayConfig& config, RenderBackend& backend,
                           MapFollower& follower, Tracker* tracker,
                           const LiveViewOptions& options);

}  // namespace confvis
