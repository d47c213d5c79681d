#pragma once
// The Vulkan rasterizer backend (design note §5, forward path): offscreen, headless, both
// stereo eyes of a wall in one multiview pass; in conformal mode every scene vertex is moved by
// the `geom` cube map after tessellation (shaders/confvis_warp.glsl). Runs on any Vulkan 1.1
// device with tessellation and geometry shaders and multiview, lavapipe included.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "confvis/backends/render_backend.hpp"
#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {

// How the eyes of a wall are drawn in stereo.
enum class StereoPasses {
  // One multiview pass where the device draws it correctly (checked once at startup by
  // rendering a clipped triangle into two views), else one pass per eye: Mesa's lavapipe 22.x
  // rasterizes clipped primitives of view 1 into view 0.
  Auto,
  Multiview,  // always one pass with VK_KHR_multiview (Vulkan 1.1 multiview)
  PerEye,     // always one pass per eye
};

// Thread-safety: a value (options): read it from any number of threads at once.
// onValidationMessage is called on the thread that calls the backend, during those calls.
struct VulkanOptions {
  // Which device renders: "" or "auto" picks the best device that supports everything confvis
  // needs (discrete GPU, then integrated, then virtual, then CPU such as lavapipe); a decimal
  // number is an index into listVulkanDevices(); anything else is matched case-insensitively
  // against the device names ("llvmpipe" is lavapipe). Error(DeviceUnsupported) when nothing
  // matches or the chosen device lacks a required feature.
  std::string device;
  // Khronos validation layer (with synchronization validation) and a debug messenger that
  // reports every warning and error; Error(DeviceUnsupported) if the layer is not installed.
  bool validation = false;
  // Receives each validation message; without one they go to stderr.
  std::function<void(const std::string&)> onValidationMessage;
  // Conformal mode: bent edges are subdivided until the drawn polyline is within this many
  // pixels (angular size of the smallest pixel of the rendered walls, seen from the reference
  // point) of the exact warped curve. Smaller is sharper and slower.
  double tessellationErrorPixels = 0.5;
  // Longest segment of a subdivided edge, degrees: long edges are subdivided even where the bend
  // measured at their midpoint is small.
  double maxSegmentDegrees = 20.0;
  StereoPasses stereoPasses = StereoPasses::Auto;
  // Conformal mode without any subdivision: a deliberately wrong render for tests and for the
  // tessellation benchmark's baseline.
  bool tessellate = true;
  // Conformal mode: triangles that the source's cut crosses through two edges are split exactly
  // along it, each side drawn up to the cut. False: they are tessellated finely and the pieces
  // across the cut dropped, leaving a band of a segment's width unshown (for tests and benchmarks).
  bool splitAlongCut = true;
  // Conformal mode: the cut vertices of triangles split along the cut are moved out to the
  // display's rim (where the ray map's coverage ends), which is where the exact warp takes the
  // cut; the geom map's extrapolation from its last texel falls short of it where the map grows
  // like a square root next to the cut, leaving a band along the rim unshown. False: the
  // extrapolated limits (for tests and benchmarks).
  bool snapCutToRim = true;
  // Conformal mode: the tessellated pieces that the cut tears (in the triangles the pre-pass
  // leaves to the geometry shader) are drawn on each side up to the cut. False: they are dropped,
  // leaving a band of a segment's width unshown beside the cut, as before issue 23 (for tests).
  bool drawTornPiecesUpToTheCut = true;
  // Conformal mode: triangles spanning more than 16 degrees seen from the warp's centre (a large
  // quad next to the viewer, a ground plane under them) are split before the warp, so that the
  // pre-pass bends pieces it can follow. False: drawn whole, as before issue 23 (for tests).
  bool splitWideTriangles = true;
  // Conformal mode: triangles lying outside the map's source field are drawn where the map's
  // extension beyond it places them: beyond the rim seen from c, but an eye off c sees the part
  // of them inside the room next to the rim, as Embree does. True: they are dropped (partly
  // outside ones through the geometry shader), as before issue 23, which left a saw-toothed band
  // along the rim for a head off c (for tests).
  bool dropOutsideSourceField = false;
  // Conformal mode: a frame whose scene, map, navigation (RenderSettings::camera) and error
  // bounds equal the previous conformal frame's reuses its compute pre-pass (warps, edge levels,
  // draw lists); head tracking alone changes none of them. False: every frame runs it (the
  // benchmark's figure for frames that navigate).
  bool reusePrepass = true;
  // Conformal mode: timestamps between the pre-pass's passes; the stats' object
  // `prepass_pass_gpu_seconds` gives each pass's GPU time (benchmarks; on lavapipe each
  // timestamp waits for the work before it).
  bool timePrepassPasses = false;
  // Conformal mode: the bent triangles' tessellation, warp and split at the cut (the pre-pass's
  // tessellated lists) run once a frame, captured by transform feedback into a buffer that every
  // wall and eye draws with its own projection, where the device has VK_EXT_transform_feedback
  // (lavapipe has; a device the application made, external_device.hpp, is not asked to).
  // False, or a device without it: every wall's and eye's draw redoes them.
  bool warpOncePerFrame = true;
  // Conformal mode, once a frame: the captured triangles are drawn with the projection and
  // headlight of the wall this many walls further on (cyclically): a deliberately wrong render
  // for tests.
  std::uint32_t capturedViewShiftForTests = 0;
  // Conformal mode, once a frame: false leaves the torn pieces' split in compute out, so the
  // geometry shader's stand-ins for them are drawn as they are (nothing): a deliberately wrong
  // render for tests.
  bool splitCapturedTornPiecesForTests = true;
  // Conformal mode: each wall draws only the flat-list triangles that may show on it (the
  // warped corners tested against its eyes' frusta in compute, every frame); false: every wall
  // draws the whole flat list. Unset: on for GPUs, off for CPU drivers. On an H200 the 1M-triangle
  // baked frame's GPU time went from 1.52x plain to 0.82x at 480-px walls (1.25x to 1.11x at
  // 1920 px); on lavapipe it saved nothing at 20k triangles and cost ~6 % at 200k
  // (backends/vulkan/README.md).
  std::optional<bool> cullFlatListPerWall;
  // Conformal mode: each wall's flat list is culled against the next wall's frusta: a
  // deliberately wrong render for tests.
  bool cullFlatListAgainstNextWallForTests = false;
};

struct VulkanDeviceInfo {
  int index = 0;       // what VulkanOptions::device accepts as a number
  std::string name;    // e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string type;    // "discrete", "integrated", "virtual", "cpu", "other"
  std::string apiVersion;
  std::vector<std::string> missing;  // required features it lacks; empty = usable
  bool automatic = false;  // the device VulkanOptions::device "" / "auto" picks
};

// Every Vulkan device the loader reports. Error(DeviceUnsupported) if no Vulkan driver is
// installed at all.
std::vector<VulkanDeviceInfo> listVulkanDevices();

// Creates the instance and device at once (so a bad --device fails before any rendering).
std::unique_ptr<RenderBackend> makeVulkanBackend(const VulkanOptions& options = {});

}  // namespace confvis
