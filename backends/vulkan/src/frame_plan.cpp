#include "frame_plan.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/gtc/constants.hpp>

#include "confvis/base/error.hpp"
#include "confvis/engine/view.hpp"

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


// Smallest angle a pixel of `wall` (lit area, w x h output pixels) subtends at c.
double smallestPixelAngle(const Wall& wall, std::uint32_t w, std::uint32_t h,
                          const glm::dvec3& c) {
  const Wall lit = wall.litRectangle();
  const double pitch = std::min(lit.widthMetres() / w, lit.heightMetres() / h);
  const double perpendicular = std::abs(glm::dot(lit.normal(), lit.lowerLeft - c));
  double farthest = 0.0;
  for (const glm::dvec3& corner :
       {lit.lowerLeft, lit.lowerRight, lit.upperLeft, lit.upperRight()})
    farthest = std::max(farthest, glm::length(corner - c));
  // A pixel at distance D, seen at obliquity cos = perpendicular / D, spans pitch * cos / D.
  return std::max(pitch * perpendicular / (farthest * farthest), 1e-9);
}

// The wall's lit rectangle relative to c with its local bend error bound: a bend of e radians
// seen from c, in direction d at obliquity cos to the wall (distance D of its plane), moves the
// drawn point by about e D / cos^2 on the wall, so errorPixels pixels of pitch p tolerate
// e = errorPixels p / D cos^2 (the smallest pixel angle alone is up to three times stricter at a
// CAVE wall's centre than at its corners).
ErrorWall errorWall(const Wall& wall, std::uint32_t w, std::uint32_t h, const glm::dvec3& c,
                    double errorPixels) {
  const Wall lit = wall.litRectangle();
  const double pitch = std::min(lit.widthMetres() / w, lit.heightMetres() / h);
  glm::dvec3 normal = lit.normal();
  double distance = glm::dot(normal, c - lit.lowerLeft);
  if (distance < 0.0) {
    normal = -normal;
    distance = -distance;
  }
  ErrorWall e;
  e.lowerLeft = glm::vec4(glm::vec3(lit.lowerLeft - c),
                          static_cast<float>(errorPixels * pitch / std::max(distance, 1e-9)));
  e.right = glm::vec4(glm::vec3(lit.right()), static_cast<float>(lit.widthMetres()));
  e.up = glm::vec4(glm::vec3(lit.up()), static_cast<float>(lit.heightMetres()));
  e.normal = glm::vec4(glm::vec3(normal), static_cast<float>(distance));
  return e;
}

}  // namespace

glm::dvec3 virtualEyePosition(const glm::dvec3& eye, const DisplayConfig& config,
                              const RetargetMap* map, const RenderSettings& settings) {
  glm::dvec3 physical = eye;
  if (settings.mode == RenderMode::Conformal) {
    const glm::dvec3 c = map->reference;
    const double distance = glm::length(eye - c);
    if (distance > 1e-12) {
      const glm::dvec3 d = (eye - c) / distance;
      if (const auto v = map->toVirtual({d.x, d.y, d.z})) physical = c + distance * *v;
    }
  }
  return settings.camera.position + settings.camera.rotation() * (physical - config.reference);
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
  plan.walls = selectWalls(config, settings);
  plan.eyes = settings.eyes;
  const bool conformal = settings.mode == RenderMode::Conformal;
  const glm::dvec3 warpCentre = conformal ? map->reference : config.reference;

  // World (virtual) -> physical frame: the inverse of p -> position + R (p - c).
  const glm::dmat3 rt = glm::transpose(settings.camera.rotation());
  glm::dmat4 worldToPhysical(rt);
  worldToPhysical[3] = glm::dvec4(config.reference - rt * settings.camera.position, 1.0);
  plan.frame.worldToPhysical = glm::mat4(worldToPhysical);
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
    const double pixelAngle = smallestPixelAngle(*wall, w, h, warpCentre);
    plan.pixelAngles.push_back(pixelAngle);
    if (conformal)
      plan.errorWalls.push_back(errorWall(*wall, w, h, warpCentre, tessellation.errorPixels));
    const glm::vec4 params(static_cast<float>(tessellation.errorPixels * pixelAngle),
                           static_cast<float>(glm::radians(tessellation.maxSegmentDegrees)),
                           static_cast<float>(4.0 * pixelAngle), tessellation.enabled ? 1.0f : 0.0f);
    for (std::size_t e = 0; e < eyes.size(); ++e) {
      const ViewOverride* custom = findViewOverride(settings.views, wall->name, plan.eyes[e]);
      const glm::dvec3 eye = custom ? overrideEyePosition(*custom) : eyes[e];
      WallView view = makeWallView(*wall, eye);  // throws if the eye cannot see the wall
      ViewData data;
      // Reverse-Z without a far plane, the near plane a tiny fraction of the wall's distance:
      // float depth resolves the same relative distances in a scene of millimetres or of
      // kilometres, and clips nothing that the ray tracer (rays from t = 0) would show.
      const double near = kNearFractionOfWallDistance * view.nearDistance;
      data.viewProj = glm::mat4(custom ? withReverseDepth(custom->projection, near) * custom->view
                                       : view.projectionVulkanReverseZ(near) * view.view);
      data.eyeVirtual = glm::vec4(glm::vec3(virtualEyePosition(eye, config, map, settings)), 1.0f);
      data.params = params;
      plan.views.push_back(data);
    }
  }
  return plan;
}

}  // namespace confvis::vulkan
