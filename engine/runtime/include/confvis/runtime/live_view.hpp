#pragma once
// The frame loop of a live display (`confvis view`): every frame polls the windows and the
// tracker, takes the follower's current map (never waiting for a re-bake), renders every wall
// for every eye its window shows, and presents each window through its swapchain. Ends after
// `frames` frames, on Esc, or when a window is closed; returns the report for view.json.
// With a FrameSync (frame_sync.hpp) the same loop runs frame-locked with other processes (a
// cluster: each shows its own walls, one decides every frame).
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "confvis/backends/render_backend.hpp"
#include "confvis/base/export.hpp"
#include "confvis/runtime/frame_sync.hpp"
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
  // The backend the factory makes is the Vulkan one, on the presenting device: that device is
  // then chosen as VulkanOptions::device says (`renderDevice`), with every rendering feature.
  bool renderOnPresentingDevice = false;
  std::string renderDevice;
  // The walls this process shows (a window each); unset: every wall. Empty: none (a cluster's
  // head node: it decides frames, opens no window and renders nothing).
  std::optional<std::vector<std::string>> walls;
  std::string windowTitle = "confvis view";  // each window's title: "TITLE: WALL | status"
};

class PresentContext;
// Makes the renderer once the presenting device exists. A VulkanRenderer
// (vulkan/external_device.hpp) made on context.handles() renders every eye straight into the
// windows' swapchain images (one blit each, nothing read back); other backends' frames are
// composed on the CPU and uploaded through a staging buffer.
using LiveBackendFactory = std::function<std::unique_ptr<RenderBackend>(const PresentContext&)>;

// `tracker` may be null (the head stays at the display's reference point). Throws Error naming
// the wall for window placement errors, and the backend's errors naming the frame.
nlohmann::json runLiveView(const DisplayConfig& config, const LiveBackendFactory& makeBackend,
                           MapFollower& follower, Tracker* tracker,
                           const LiveViewOptions& options);
// Frame-locked through `sync`: `follower` and `tracker` are used (and needed: `follower` not
// null) only where sync.decides(); options.walls picks this process's windows. Where it decides,
// the report holds what the single process reports; elsewhere the same without re-bakes and
// tracker counts.
nlohmann::json runLiveView(const DisplayConfig& config, const LiveBackendFactory& makeBackend,
                           MapFollower* follower, Tracker* tracker,
                           const LiveViewOptions& options, FrameSync& sync);
// The same with a backend made beforehand (its frames always go through the CPU).
nlohmann::json runLiveView(const DisplayConfig& config, RenderBackend& backend,
                           MapFollower& follower, Tracker* tracker,
                           const LiveViewOptions& options);

}  // namespace confvis
