#pragma once
// A frame's statistics, typed. Backends record them in RenderResult::stats (JSON, the form
// render.json and walk.json write); frameStats() reads them into this struct, so an application
// neither parses JSON nor guesses key names. Fields a backend does not measure stay empty.
//
// example: frame_stats (compiled and run by the test suite, tests/examples/)
//   RenderResult images;
//   backend.renderInto(display, &map, settings, images);
//   const FrameStats stats = frameStats(images);
//   overlay("%.1f ms", 1e3 * stats.seconds);
//
// Thread-safety: a value; frameStats only reads its argument.
#include <cstdint>
#include <optional>
#include <string>

#include "confvis/backends/render_backend.hpp"

namespace confvis {

struct FrameStats {
  std::string backend;            // "embree" or "vulkan"
  // Wall-clock seconds of the frame: Embree, tracing and shading every image ("render_seconds",
  // the map's direction tables apart: mapBuildSeconds); Vulkan, the whole render call ("seconds").
  double seconds = 0.0;
  std::uint64_t sceneTriangles = 0;  // triangles of the scene set with setScene
  std::optional<double> gpuSeconds;  // Vulkan: the device's own time (timestamps), where it has them
  std::string device;                // Vulkan: the device's name; empty for Embree

  // Embree.
  std::optional<double> mapBuildSeconds;  // direction tables of new maps or wall sizes
  // One per pixel and sample (more for curved rays), retraced ones included.
  std::optional<std::uint64_t> cameraRays;
  std::optional<std::uint64_t> retracedRays;   // camera rays traced a second time
  std::optional<std::uint64_t> occlusionRays;  // ambient occlusion
  std::optional<double> raysPerSecond;         // (camera + occlusion rays) / seconds
  std::optional<int> threads;                  // TBB worker threads the frame could use

  // Vulkan, conformal mode: the compute pre-pass that warps the scene for the map.
  std::optional<double> prepassSeconds;
  std::optional<double> prepassGpuSeconds;
  std::optional<bool> prepassReused;  // same scene, map, navigation: last frame's pre-pass reused
};

// Reads result.stats. Throws Error(InvalidInput) naming the key when "backend" or the frame's
// seconds are missing or not of their type (a result no backend made).
FrameStats frameStats(const RenderResult& result);

}  // namespace confvis
