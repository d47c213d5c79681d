#pragma once
// The confvis public API in one include (link confvis::confvis): every public header of every
// module (tests/examples/umbrella_header_test.cpp checks that none is left out). The headers of
// the Embree scene internals and of the Vulkan warp interface come in where the application can
// compile them (Embree's and Vulkan's headers installed). Conformal visualization for
// partially-immersive displays: load a display (confvis JSON, SGCT, ParaView .pvx), track the
// head, get per-wall per-eye off-axis views, keep a baked RetargetMap following the head, and
// render through it with a RenderBackend or sample it in your own renderer.
// Integration guide: README.md, "Using confvis in an application".
//
// Thread-safety: the value types (DisplayConfig, Wall, HeadPose, WallView, RetargetMap, CubeMap,
// ImageRGBA, Scene, RenderSettings, RenderResult, ...) are safe to read from any number of threads
// at once and need exclusive access to be changed; free functions share no state beyond their
// arguments and the files they read or write (bakes and renders start worker threads of their
// own). Every class states its own.

// Errors, images, cube maps, EXR/PNG files.
#include "confvis/base/atomic_file.hpp"
#include "confvis/base/cube_map.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/export.hpp"
#include "confvis/base/exr_io.hpp"
#include "confvis/base/file_checks.hpp"
#include "confvis/base/image.hpp"
#include "confvis/base/png_io.hpp"
#include "confvis/base/progress.hpp"
#include "confvis/base/stopwatch.hpp"
#include "confvis/base/vec3.hpp"
#include "confvis/base/checksum.hpp"
#include "confvis/base/input_limits.hpp"
#include "confvis/base/json_text.hpp"
#include "confvis/base/text_encoding.hpp"

// Displays, viewers and their off-axis views, head tracking, scenes.
#include "confvis/engine/builtin_scenes.hpp"
#include "confvis/engine/display_config.hpp"
#include "confvis/engine/display_import.hpp"
#include "confvis/engine/number_text.hpp"
#include "confvis/engine/scene.hpp"
#include "confvis/engine/scene_loader.hpp"
#include "confvis/runtime/tracker.hpp"
#include "confvis/runtime/tracker_factory.hpp"
#include "confvis/engine/version.hpp"
#include "confvis/engine/view.hpp"
#include "confvis/engine/viewer.hpp"
#include "confvis/engine/default_edge_length.hpp"
#include "confvis/engine/display_output.hpp"
#include "confvis/engine/display_surfaces.hpp"
#include "confvis/engine/scene_units.hpp"
#include "confvis/engine/tracking_config.hpp"

// The conformal map of a display, baked into direction cube maps (bakeDisplay: config -> map,
// with the on-disk cache), their files and their measured quality.
#include "confvis/conformal/bake.hpp"
#include "confvis/conformal/bake_display.hpp"
#include "confvis/conformal/bake_preset.hpp"
#include "confvis/conformal/bake_files.hpp"
#include "confvis/conformal/baked_map_quality.hpp"
#include "confvis/conformal/display_map.hpp"
#include "confvis/conformal/retarget_map.hpp"

// The conformal machinery itself: meshes, circle-packing metrics, the Ricci flow, disk maps,
// Mobius alignment, distortion measures, display templates.
#include "confvis/conformal/circle_packing.hpp"
#include "confvis/conformal/disk_map.hpp"
#include "confvis/conformal/display_template.hpp"
#include "confvis/conformal/distortion.hpp"
#include "confvis/conformal/intrinsic_triangulation.hpp"
#include "confvis/conformal/mesh.hpp"
#include "confvis/conformal/mesh_generators.hpp"
#include "confvis/conformal/mesh_source.hpp"
#include "confvis/conformal/mobius.hpp"
#include "confvis/conformal/obj_output.hpp"
#include "confvis/conformal/real_mesh_map.hpp"
#include "confvis/conformal/ricci_flow.hpp"
#include "confvis/conformal/bake_verdict.hpp"
#include "confvis/conformal/map_alignment_quality.hpp"
#include "confvis/conformal/map_accuracy.hpp"
#include "confvis/conformal/map_reference_extrapolation.hpp"
#include "confvis/conformal/map_interpolation.hpp"

// Keeping the map around the tracked head.
#include "confvis/runtime/background_bake.hpp"
#include "confvis/runtime/map_follower.hpp"
#include "confvis/runtime/tracker_factory.hpp"
#include "confvis/runtime/udp_tracker.hpp"

// The live display: windows, swapchains, the frame loop (confvis view), and the frame state a
// cluster shares (confvis/runtime/cluster.hpp itself is the cluster component: it needs MPI).
#include "confvis/runtime/background_priority.hpp"
#include "confvis/runtime/camera_controls.hpp"
#include "confvis/runtime/display_window.hpp"
#include "confvis/runtime/frame_log.hpp"
#include "confvis/runtime/frame_state.hpp"
#include "confvis/runtime/frame_sync.hpp"
#include "confvis/runtime/live_view.hpp"
#include "confvis/runtime/present_context.hpp"
#include "confvis/runtime/swapchain_state.hpp"
#include "confvis/runtime/tracker_packets.hpp"
#include "confvis/runtime/wall_assignment.hpp"
#include "confvis/runtime/window_content.hpp"
#include "confvis/runtime/window_plan.hpp"
#include "confvis/runtime/window_presenter.hpp"
#include "confvis/runtime/zero_extent_injection.hpp"

// Rendering through the map (backends: Embree, Vulkan): render plans and eyeName(), typed frame
// statistics (FrameStats), the warp in closed form, analytic test maps, map files (readRetargetMapDirectory: a baked map from disk).
#include "confvis/backends/analytic_maps.hpp"
#include "confvis/backends/conformal_warp.hpp"
#include "confvis/backends/frame_stats.hpp"
#include "confvis/backends/headlight.hpp"
#include "confvis/backends/render_backend.hpp"
#include "confvis/backends/edge_blend_output.hpp"
#include "confvis/backends/render_output.hpp"
#include "confvis/backends/render_plan.hpp"
#include "confvis/backends/retarget_map_files.hpp"
#include "confvis/backends/view_override.hpp"
#include "confvis/backends/wall_map_grid.hpp"
#include "confvis/backends/embree/embree_backend.hpp"
#include "confvis/backends/vulkan_backend.hpp"
#include "confvis/backends/vulkan/device_requirements.hpp"
#if __has_include(<embree3/rtcore.h>)
#include "confvis/backends/embree/embree_device.hpp"
#include "confvis/backends/embree/embree_scene.hpp"
#endif
// An application's own Vulkan renderer: the warp's descriptor layout and upload data, with the
// GLSL include confvis_warp.glsl (installed in ${confvis_SHADER_DIR}).
#if __has_include(<vulkan/vulkan.h>)
#include "confvis/backends/vulkan/warp_interface.hpp"
// ... and the map upload, per-wall bounds and conformal pre-pass on the application's device.
#include "confvis/backends/vulkan/byo_descriptors.hpp"
#include "confvis/backends/vulkan/byo_device.hpp"
#include "confvis/backends/vulkan/byo_frame.hpp"
#include "confvis/backends/vulkan/byo_pipeline.hpp"
#include "confvis/backends/vulkan/byo_prepass.hpp"
#include "confvis/backends/vulkan/byo_upload.hpp"
// The Vulkan backend on the application's device, rendering into its images.
#include "confvis/backends/vulkan/external_device.hpp"
#endif
