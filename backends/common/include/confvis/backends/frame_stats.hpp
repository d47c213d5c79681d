#pragma once
// A frame's statistics, typed: every backend fills RenderResult::stats with this struct while it
// renders. JSON is made only where a file is written (toJson: render.json's "backend" object,
// whose keys are named beside each field below). Times are wall-clock seconds of
// std::chrono::steady_clock unless a field says GPU; counts are per frame (one render or
// renderInto call, every wall and eye it rendered).
//
// example: frame_stats (compiled and run by the test suite, tests/examples/)
//   RenderResult images;
//   backend.renderInto(display, &map, settings, images);
//   const FrameStats& stats = images.stats;
//   overlay("%.1f ms", 1e3 * stats.seconds);
//
// Thread-safety: plain values; read them from any number of threads at once, write from one.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "confvis/base/export.hpp"
#include "confvis/engine/viewer.hpp"

namespace confvis CONFVIS_API {

// Embree: one traced image (a wall for an eye).
struct EmbreeImageStats {
  std::string wall;       // "wall": the wall's name in the display config
  Eye eye = Eye::Center;  // "eye": eyeName(eye)
  int width = 0;          // "width", "height": the image's size in pixels
  int height = 0;
  double seconds = 0.0;   // "seconds": tracing and shading this image
};

// What only the Embree ray tracer measures.
struct EmbreeFrameStats {
  int threads = 0;                // "threads": TBB worker threads the frame could use (>= 1)
  double bvhBuildSeconds = 0.0;   // "bvh_build_seconds": the scene's BVH build (at setScene)
  // "map_build_seconds": this frame's share of building per-wall direction tables and map grids
  // for a new map or wall size; 0 when every table was cached from an earlier frame.
  double mapBuildSeconds = 0.0;
  // "direction_table_samples": directions looked up from the cached per-pixel tables (centre
  // eye, conformal mode) instead of traced through the map.
  std::uint64_t directionTableSamples = 0;
  // "cached_direction_table_bytes": bytes the backend keeps in direction tables after this frame
  // (tables of images not rendered in the last few renders are given back).
  std::uint64_t cachedDirectionTableBytes = 0;
  std::uint64_t cachedWallGrids = 0;  // "cached_wall_grids": per-wall map grids kept after it
  // "camera_rays": rays shot from the eye, one per pixel and sample (a curved stereo ray counts
  // once per traced segment), retraced ones included.
  std::uint64_t cameraRays = 0;
  std::uint64_t occlusionRays = 0;  // "occlusion_rays": ambient occlusion (0 without --ao)
  // "retraced_rays": camera rays traced a second time, slightly turned (a ray that missed while
  // its neighbours hit, as one through a vertex shared by several triangles can).
  std::uint64_t retracedRays = 0;
  std::string shadingSimd;          // "shading_simd": the shading kernel, "sse2" or "avx2"
  // "rays_per_second": (cameraRays + occlusionRays) / FrameStats::seconds; 0 for a 0 s frame.
  double raysPerSecond = 0.0;
  // "curved_ray_segments": straight segments per bent eye ray (exact stereo: the backend's
  // option; fast stereo: 1); only for conformal frames with off-centre eyes.
  std::optional<int> curvedRaySegments;
  std::vector<EmbreeImageStats> images;  // "images": per image, in RenderResult::images' order
};

// What only the Vulkan rasterizer's conformal mode measures: the compute pre-pass that warps the
// scene's vertices for the map and sorts its triangles.
struct VulkanConformalStats {
  double tessellationErrorPixels = 0.0;  // "tessellation_error_pixels": VulkanOptions' threshold
  bool tessellation = true;              // "tessellation": VulkanOptions::tessellate
  // "triangles_split_before_warp": scene triangles split for being too wide seen from the
  // warp's centre (VulkanOptions::splitWideTriangles); 0 when none was.
  std::uint64_t trianglesSplitBeforeWarp = 0;
  std::uint64_t trianglesDrawnFlat = 0;    // "triangles_drawn_flat": warped at their corners only
  // "triangles_tessellated": subdivided along their warped edges (with or without the
  // geometry shader).
  std::uint64_t trianglesTessellated = 0;
  // "triangles_through_geometry_shader": of those, drawn through the geometry shader that drops
  // pieces across the map's cut.
  std::uint64_t trianglesThroughGeometryShader = 0;
  // "triangles_split_along_cut": drawn in flat pieces on each side of the map's cut.
  std::uint64_t trianglesSplitAlongCut = 0;
  double prepassSeconds = 0.0;  // "prepass_seconds": the pre-pass's submission (0 where reused)
  // "prepass_gpu_seconds": its GPU time (0 where reused; absent where the queue writes no
  // timestamps).
  std::optional<double> prepassGpuSeconds;
  // "prepass_reused": the scene, map and navigation were those of the previous conformal frame,
  // whose pre-pass results were drawn again without running it.
  bool prepassReused = false;
  // "prepass_pass_gpu_seconds": each compute pass's GPU time by pass name, only where
  // VulkanOptions::timePrepassPasses asked for them and the pre-pass ran.
  std::map<std::string, double> passGpuSeconds;
  // Per wall drawn (the plan's order): the flat-list triangles its pass drew after the per-wall
  // cull (VulkanOptions::cullFlatListPerWall; empty where it is off). Not written to the JSON.
  std::vector<std::uint64_t> flatTrianglesPerWall;
};

// What only the Vulkan rasterizer measures.
struct VulkanFrameStats {
  std::string device;   // "device": the physical device's name (e.g. "llvmpipe (LLVM 15.0.6, ...)")
  bool conformal = false;    // "mode": "conformal" or "plain"
  std::uint64_t walls = 0;   // "walls": walls rendered
  int viewsPerPass = 1;      // "views_per_pass": eyes drawn by one render pass (multiview)
  bool multiview = false;    // "stereo_passes": "multiview" or "per-eye"
  // "gpu_seconds": the device's own time for the frame (timestamps: pre-pass and every wall's
  // render pass, without the readback copies); absent where the queue writes no timestamps.
  std::optional<double> gpuSeconds;
  std::optional<VulkanConformalStats> conformalPrepass;  // conformal mode only (see above)
};

struct FrameStats {
  std::string backend;  // "backend": RenderBackend::name(), "embree" or "vulkan"
  // The frame's wall-clock seconds ("render_seconds" for Embree: tracing and shading every image,
  // the map's direction tables apart, see EmbreeFrameStats::mapBuildSeconds; "seconds" for
  // Vulkan: the whole render call, readback included). Greater than 0 for every backend's frame.
  double seconds = 0.0;
  // Triangles of the scene given to setScene ("scene_triangles" for Embree, "triangles" for
  // Vulkan).
  std::uint64_t sceneTriangles = 0;
  std::optional<EmbreeFrameStats> embree;  // set by the Embree backend, and only by it
  std::optional<VulkanFrameStats> vulkan;  // set by the Vulkan backend, and only by it
};

// The JSON written to render.json ("backend") and the cluster's reports: the keys named above,
// a backend's own keys beside the shared ones; optional fields absent where empty.
nlohmann::json toJson(const FrameStats& stats);

}  // namespace confvis
