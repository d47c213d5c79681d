#pragma once
// The confvis public API in one include (link confvis::confvis). Conformal visualization for
// partially-immersive displays: load a display (confvis JSON, SGCT, ParaView .pvx), track the
// head, get per-wall per-eye off-axis views, keep a baked RetargetMap following the head, and
// render through it with a RenderBackend or sample it in your own renderer.
// Integration guide: README.md, "Using confvis in an application".

// Errors, images, cube maps, EXR/PNG files.
#include "confvis/base/atomic_file.hpp"
#include "confvis/base/cube_map.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/exr_io.hpp"
#include "confvis/base/image.hpp"
#include "confvis/base/png_io.hpp"
#include "confvis/base/progress.hpp"
#include "confvis/base/vec3.hpp"

// Displays, viewers and their off-axis views, head tracking, scenes.
#include "confvis/engine/builtin_scenes.hpp"
#include "confvis/engine/display_config.hpp"
#include "confvis/engine/display_import.hpp"
#include "confvis/engine/scene.hpp"
#include "confvis/engine/scene_loader.hpp"
#include "confvis/runtime/tracker.hpp"
#include "confvis/engine/version.hpp"
#include "confvis/engine/view.hpp"
#include "confvis/engine/viewer.hpp"

// The conformal map of a display, baked into direction cube maps (bakeDisplay: config -> map,
// with the on-disk cache), their files and their measured quality.
#include "confvis/conformal/bake.hpp"
#include "confvis/conformal/bake_display.hpp"
#include "confvis/conformal/bake_files.hpp"
#include "confvis/conformal/baked_map_quality.hpp"
#include "confvis/conformal/display_map.hpp"
#include "confvis/conformal/retarget_map.hpp"

// Keeping the map around the tracked head.
#include "confvis/runtime/map_follower.hpp"
#include "confvis/runtime/tracker_factory.hpp"
#include "confvis/runtime/udp_tracker.hpp"

// Rendering through the map (backends: Embree, Vulkan).
#include "confvis/backends/render_backend.hpp"
#include "confvis/backends/render_output.hpp"
#include "confvis/backends/embree/embree_backend.hpp"
#include "confvis/backends/vulkan_backend.hpp"
