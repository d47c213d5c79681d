#pragma once
// The one interface both renderers implement (Filament style: one backend interface, one
// implementation per API). A backend renders every requested wall for every requested eye of a
// display, either plainly (the ordinary off-axis view every CAVE package draws) or through the
// conformal map (design note §5). Images come back in memory; render_output.hpp writes them.
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "confvis/backends/frame_stats.hpp"
#include "confvis/backends/view_override.hpp"
#include "confvis/base/export.hpp"
#include "confvis/base/image.hpp"
#include "confvis/conformal/retarget_map.hpp"
#include "confvis/engine/display_config.hpp"
#include "confvis/engine/scene.hpp"
#include "confvis/engine/viewer.hpp"

namespace confvis CONFVIS_API {

enum class RenderMode { Plain, Conformal };
// Stereo eyes in conformal mode (design note §5): Exact marches the bent virtual ray
// W(e + t (p - e)) as straight segments; Fast shoots one straight ray from e towards W(p).
enum class StereoRays { Exact, Fast };

// Navigation in the virtual world, separate from the tracked head: the physical frame's
// reference point c is placed at `position`, and the physical frame is turned by yaw (degrees,
// about +y, positive turns left) then pitch (degrees, about the turned +x, positive looks up).
// A physical point p is the virtual point position + R (p - c).
// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
struct VirtualCamera {
  glm::dvec3 position{0.0};
  double yawDegrees = 0.0;
  double pitchDegrees = 0.0;
  glm::dmat3 rotation() const;
};

// Thread-safety: a value (options): read it from any number of threads at once.
struct RenderSettings {
  RenderMode mode = RenderMode::Conformal;
  std::vector<Eye> eyes{Eye::Center};  // mono: {Center}; stereo: {Left, Right}
  StereoRays stereoRays = StereoRays::Exact;
  std::vector<std::string> walls;      // names; empty = every wall, in config order
  int samplesPerPixel = 1;
  bool ambientOcclusion = false;
  HeadPose head;                       // physical head pose (eyes derive from it)
  VirtualCamera camera;
  // Output size = round(wall resolution * resolutionScale), at least 1 pixel; tests render small.
  double resolutionScale = 1.0;
  bool showProgress = false;           // progress bar on stderr
  // Application-supplied view and projection for some walls' eyes (view_override.hpp); the
  // others get the off-axis view of `head`. Both backends, both modes: in conformal mode the
  // overridden eye's rays (Embree) or the projected warped vertices (Vulkan) go through the map
  // as the computed view's do.
  std::vector<ViewOverride> views;
};

// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
struct WallImage {
  std::string wall;
  Eye eye = Eye::Center;
  ImageRGBA image;  // linear RGB, alpha 1 where something was drawn
};

// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
struct RenderResult {
  std::vector<WallImage> images;   // walls in settings order (config order), eyes in settings order
  FrameStats stats;  // the frame's times and counts (frame_stats.hpp); toJson for files
};

// Thread-safety: not thread-safe; call a backend from one thread at a time (it keeps the scene,
// the device and per-frame state). Separate backends may render on separate threads. The config,
// map and scene handed in are only read, and may be shared with other readers meanwhile.
class RenderBackend {
 public:
  virtual ~RenderBackend() = default;
  virtual std::string name() const = 0;
  // Builds acceleration structures / uploads buffers; call once per scene. Keeps no reference.
  virtual void setScene(const Scene& scene) = 0;
  // Does now what the first frame of `settings` on `config` would do once (the Vulkan backend
  // compiles its pipelines on first use: 12.8 s on lavapipe), so that a frame loop's first
  // frame costs what the others do. Call after setScene, before the loop, with the loop's
  // settings. This default renders one frame and drops it: conformal mode through the identity
  // map around config.reference, so no bake is needed.
  virtual void prepare(const DisplayConfig& config, const RenderSettings& settings);
  // `map` is required in conformal mode (Error(InvalidInput) otherwise) and ignored in plain mode.
  // Unknown wall names give Error(InvalidInput) naming the wall.
  virtual RenderResult render(const DisplayConfig& config, const RetargetMap* map,
                              const RenderSettings& settings) = 0;
  // The same frame rendered into `result`, for frame loops: a backend may keep the pixel storage
  // of result's images where an image of the same size comes back (no fresh allocation, no page
  // faults). The images and stats are replaced as by render(); this default does just that.
  virtual void renderInto(const DisplayConfig& config, const RetargetMap* map,
                          const RenderSettings& settings, RenderResult& result) {
    result = render(config, map, settings);
  }
};

}  // namespace confvis
