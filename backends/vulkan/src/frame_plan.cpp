#include "frame_plan.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/gtc/constants.hpp>

#include "confvis/base/error.hpp"
#include "confvis/backends/vulkan/byo_frame.hpp"
#include "confvis/engine/view.hpp"
#include "error_walls.hpp"

namespace confvis::vulkan {
namespace {

std::vector<const Wall*> selectWalls(const DisplayConfig& config, const RenderSettings& settings) {
  std::vector<const Wall*> walls;
  if (settings.walls.empty()) {
    for (const Wall& wall : config.walls) walls.push_back(&wall);
    return walls;
  }
  for (const std::string& name : settings.walls) config.wall(name);  // throws for unknown names
  for (const Wall& wall : config.walls)  // config order, as RenderResult promises
    if (std::find(settings.walls.begin(), settings.walls.end(), wall.name) != settings.walls.end())
      walls.push_back(&wall);
  return walls;
}

void checkSettings(const RenderSettings& settings, const RetargetMap* map, std::uint32_t maxViews) {
  if (settings.eyes.empty())
    throw Error(ErrorCode::InvalidInput, "render settings: no eye to render");
  if (settings.eyes.size() > maxViews)
    throw Error(ErrorCode::InvalidInput,
                "render settings: " + std::to_string(settings.eyes.size()) +
                    " eyes, but the Vulkan device renders at most " + std::to_string(maxViews) +
                    " views in one pass");
  if (!(settings.resolutionScale > 0.0) || !std::isfinite(settings.resolutionScale))
    throw Error(ErrorCode::InvalidInput, "render settings: resolution scale must be positive");
  if (settings.samplesPerPixel != 1)
    throw Error(ErrorCode::InvalidInput,
                "the Vulkan backend renders 1 sample per pixel (got " +
                    std::to_string(settings.samplesPerPixel) + "); use the Embree backend for --spp");
  if (settings.ambientOcclusion)
    throw Error(ErrorCode::InvalidInput,
                "the Vulkan backend has no ambient occlusion; use the Embree backend");
  if (settings.mode == RenderMode::Conformal && map == nullptr)
    throw Error(ErrorCode::InvalidInput, "conformal rendering needs a retarget map");
  if (settings.mode == RenderMode::Conformal && !isFinite(map->reference))
    throw Error(ErrorCode::InvalidInput, "retarget map: reference point is not finite");
}

}  // namespace

glm::dvec3 virtualEyePosition(const glm::dvec3& eye, const DisplayConfig& config,
                              const RetargetMap* map, const RenderSettings& settings) {
  return headlightPosition(eye, config, settings.mode == RenderMode::Conformal ? map : nullptr,
                           settings.camera);
}

FramePlan planFrame(const DisplayConfig& config, const RetargetMap* map,
                    const RenderSettings& settings, const TessellationOptions& tessellation,
                    std::uint32_t maxViews) {
  checkSettings(settings, map, maxViews);
  std::vector<std::string> wallNames;
  for (const Wall& wall : config.walls) wallNames.push_back(wall.name);
  checkViewOverrides(settings.views, wallNames);
  FramePlan plan;
  plan.splitAlongCut = tessellation.splitAlongCut;
  plan.snapCutToRim = tessellation.snapCutToRim;
  plan.reusePrepass = tessellation.reusePrepass;
  plan.dropOutsideSourceField = tessellation.dropOutsideSourceField;
  plan.warpOncePerFrame = tessellation.warpOncePerFrame;
  plan.capturedViewShiftForTests = tessellation.capturedViewShiftForTests;
  plan.splitCapturedTornPiecesForTests = tessellation.splitCapturedTornPiecesForTests;
  plan.cullFlatListPerWall = tessellation.cullFlatListPerWall;
  plan.cullFlatListAgainstNextWallForTests = tessellation.cullFlatListAgainstNextWallForTests;
  plan.walls = selectWalls(config, settings);
  plan.eyes = settings.eyes;
  const bool conformal = settings.mode == RenderMode::Conformal;
  const glm::dvec3 warpCentre = conformal ? map->reference : config.reference;

  plan.frame.worldToPhysical = glm::mat4(worldToPhysical(config, settings.camera));
  plan.frame.warpCentre = glm::vec4(glm::vec3(warpCentre), 1.0f);

  std::vector<glm::dvec3> eyes;
  for (Eye eye : plan.eyes) eyes.push_back(eyePosition(settings.head, eye, config.eyeSeparation));

  for (const Wall* wall : plan.walls) {
    const auto scaled = [&](int pixels) {
      return static_cast<std::uint32_t>(
          std::max(1.0, std::round(pixels * settings.resolutionScale)));
    };
    const std::uint32_t w = scaled(wall->width), h = scaled(wall->height);
    plan.widths.push_back(w);
    plan.heights.push_back(h);
    const WallWarpBounds bounds = wallWarpBounds(
        *wall, w, h, warpCentre, {tessellation.errorPixels, tessellation.maxSegmentDegrees});
    plan.pixelAngles.push_back(bounds.pixelAngle);
    if (conformal)
      plan.errorWalls.push_back(errorWall(*wall, w, h, warpCentre, tessellation.errorPixels));
    // w: 0 untessellated, else 1 + the geometry shader's switches (confvis_render_common.glsl).
    const float geometryShaderSwitches = (tessellation.snapCutToRim ? 0.0f : 1.0f) +
                                         (tessellation.drawTornPiecesUpToTheCut ? 0.0f : 2.0f);
    const glm::vec4 params(static_cast<float>(bounds.errorAngle),
                           static_cast<float>(bounds.maxSegmentAngle),
                           static_cast<float>(bounds.cutGapAngle),
                           tessellation.enabled ? 1.0f + geometryShaderSwitches : 0.0f);
    for (std::size_t e = 0; e < eyes.size(); ++e) {
      const ViewOverride* custom = findViewOverride(settings.views, wall->name, plan.eyes[e]);
      const glm::dvec3 eye = custom ? overrideEyePosition(*custom) : eyes[e];
      ViewData data;
      if (custom) {  // the application's matrices with wallViewProjection's reverse-Z depth
        const WallView view = makeWallView(*wall, eye);  // throws if the eye cannot see the wall
        data.viewProj = glm::mat4(
            withReverseDepth(custom->projection, kNearFractionOfWallDistance * view.nearDistance) *
            custom->view);
      } else {
        data.viewProj = glm::mat4(wallViewProjection(*wall, eye));
      }
      data.eyeVirtual = glm::vec4(glm::vec3(virtualEyePosition(eye, config, map, settings)), 1.0f);
      data.params = params;
      plan.views.push_back(data);
    }
  }
  return plan;
}

}  // namespace confvis::vulkan
