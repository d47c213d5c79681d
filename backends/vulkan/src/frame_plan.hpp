#pragma once
// Everything a frame needs before any Vulkan call: which walls and eyes, output sizes, the
// navigation transform, per wall-and-eye projection matrices, headlight positions and the
// tessellation tolerances. Validates the request (Error(InvalidInput) naming the culprit).
#include <cstdint>
#include <vector>

#include "confvis/backends/render_backend.hpp"
#include "pipelines.hpp"

namespace confvis::vulkan {

struct TessellationOptions {
  double errorPixels = 0.5;
  double maxSegmentDegrees = 20.0;
  bool enabled = true;
  bool splitAlongCut = true;  // VulkanOptions::splitAlongCut
  bool reusePrepass = true;   // VulkanOptions::reusePrepass
  bool snapCutToRim = true;   // VulkanOptions::snapCutToRim
  bool dropOutsideSourceField = false;  // VulkanOptions::dropOutsideSourceField
  bool drawTornPiecesUpToTheCut = true;  // VulkanOptions::drawTornPiecesUpToTheCut
  bool warpOncePerFrame = true;          // VulkanOptions::warpOncePerFrame
  std::uint32_t capturedViewShiftForTests = 0;  // VulkanOptions::capturedViewShiftForTests
  bool splitCapturedTornPiecesForTests = true;  // VulkanOptions::splitCapturedTornPiecesForTests
  bool cullFlatListPerWall = false;                 // VulkanOptions::cullFlatListPerWall
  bool cullFlatListAgainstNextWallForTests = false;  // VulkanOptions::cullFlatListAgainst...
};

struct FramePlan {
  std::vector<const Wall*> walls;          // in config order
  std::vector<Eye> eyes;                   // multiview layer i = eyes[i]
  std::vector<std::uint32_t> widths, heights;  // per wall
  std::vector<double> pixelAngles;         // per wall: smallest pixel seen from c, radians
  FrameUniforms frame{};
  std::vector<ViewData> views;             // index wall * eyes.size() + eye
  std::vector<ErrorWall> errorWalls;       // conformal: per wall, its local bend error bound
  bool splitAlongCut = true;  // TessellationOptions::splitAlongCut
  bool snapCutToRim = true;   // TessellationOptions::snapCutToRim
  bool reusePrepass = true;   // TessellationOptions::reusePrepass
  bool dropOutsideSourceField = false;  // TessellationOptions::dropOutsideSourceField
  bool warpOncePerFrame = true;          // TessellationOptions::warpOncePerFrame
  std::uint32_t capturedViewShiftForTests = 0;  // TessellationOptions::capturedViewShiftForTests
  bool splitCapturedTornPiecesForTests = true;  // TessellationOptions::splitCapturedTornPieces...
  bool cullFlatListPerWall = false;                 // TessellationOptions::cullFlatListPerWall
  bool cullFlatListAgainstNextWallForTests = false;  // TessellationOptions::cullFlatListAgainst...
};

// `map` must be non-null in conformal mode; `maxViews` is the device's multiview limit.
FramePlan planFrame(const DisplayConfig& config, const RetargetMap* map,
                    const RenderSettings& settings, const TessellationOptions& tessellation,
                    std::uint32_t maxViews);

// Each view's near plane, as a share of the eye's distance to the wall plane (reverse-Z keeps
// the float depth's relative precision from it to infinity, so it may be this small).
inline constexpr double kNearFractionOfWallDistance = 1e-5;

// Where the headlight of `eye` sits in the virtual world: the eye itself in plain mode; in
// conformal mode the start of its virtual rays, c + |e - c| T_ray(dir(e - c)) (the eye itself
// where the map has no display behind that direction).
glm::dvec3 virtualEyePosition(const glm::dvec3& eye, const DisplayConfig& config,
                              const RetargetMap* map, const RenderSettings& settings);

}  // namespace confvis::vulkan
