#include "confvis/backends/render_plan.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "confvis/base/error.hpp"

namespace confvis {

namespace {

// Beyond these a number is a typo, not a setting: the ray tracer works in float, and a camera at
// 1e18 m breaks its assumptions (Embree asserts) instead of rendering.
constexpr double kMaxCoordinateMetres = 1e6;
constexpr double kMaxAngleDegrees = 36000.0;
constexpr double kMaxOutputPixels = 65536.0;  // per side, as for a wall's own resolution

void checkPosition(const char* what, const glm::dvec3& p) {
  for (int i = 0; i < 3; ++i)
    if (!(std::abs(p[i]) <= kMaxCoordinateMetres))
      throw Error(ErrorCode::InvalidInput,
                  std::string(what) + " (" + std::to_string(p.x) + ", " + std::to_string(p.y) +
                      ", " + std::to_string(p.z) + ") must lie within " +
                      std::to_string(static_cast<long long>(kMaxCoordinateMetres)) +
                      " m of the origin on every axis");
}

void checkAngle(const char* what, double degrees) {
  if (!(std::abs(degrees) <= kMaxAngleDegrees))
    throw Error(ErrorCode::InvalidInput, std::string(what) + " must be within +-" +
                                             std::to_string(static_cast<int>(kMaxAngleDegrees)) +
                                             " degrees, got " + std::to_string(degrees));
}

int outputPixels(int wallPixels, double scale) {
  return std::max(1, static_cast<int>(std::lround(wallPixels * scale)));
}

void checkMap(const DisplayConfig& config, const RetargetMap* map) {
  if (!map)
    throw Error(ErrorCode::InvalidInput,
                "conformal rendering of display '" + config.name + "' needs a retarget map");
  const glm::dvec3 mapReference(map->reference.x, map->reference.y, map->reference.z);
  if (!(glm::length(mapReference - config.reference) <= 1e-6))
    throw Error(ErrorCode::InvalidInput,
                "the retarget map was baked around (" + std::to_string(mapReference.x) + ", " +
                    std::to_string(mapReference.y) + ", " + std::to_string(mapReference.z) +
                    ") but display '" + config.name + "' has its reference point at (" +
                    std::to_string(config.reference.x) + ", " +
                    std::to_string(config.reference.y) + ", " +
                    std::to_string(config.reference.z) + ")");
}

}  // namespace

const char* eyeName(Eye eye) noexcept {
  switch (eye) {
    case Eye::Left: return "left";
    case Eye::Center: return "center";
    case Eye::Right: return "right";
  }
  return "?";
}

const char* modeName(RenderMode mode) noexcept {
  return mode == RenderMode::Plain ? "plain" : "conformal";
}

const char* stereoRaysName(StereoRays rays) noexcept {
  return rays == StereoRays::Exact ? "exact" : "fast";
}

RenderPlan planRender(const DisplayConfig& config, const RetargetMap* map,
                      const RenderSettings& settings) {
  if (settings.eyes.empty())
    throw Error(ErrorCode::InvalidInput, "render settings name no eye");
  for (std::size_t i = 0; i < settings.eyes.size(); ++i)
    if (std::count(settings.eyes.begin(), settings.eyes.end(), settings.eyes[i]) > 1)
      throw Error(ErrorCode::InvalidInput,
                  std::string("render settings name the ") + eyeName(settings.eyes[i]) +
                      " eye twice");
  if (settings.samplesPerPixel < 1 || settings.samplesPerPixel > 4096)
    throw Error(ErrorCode::InvalidInput, "samples per pixel must be 1..4096, got " +
                                             std::to_string(settings.samplesPerPixel));
  if (!(settings.resolutionScale > 0.0) || !std::isfinite(settings.resolutionScale))
    throw Error(ErrorCode::InvalidInput, "resolution scale must be a positive number, got " +
                                             std::to_string(settings.resolutionScale));
  checkPosition("the virtual camera position", settings.camera.position);
  checkAngle("the virtual camera yaw", settings.camera.yawDegrees);
  checkAngle("the virtual camera pitch", settings.camera.pitchDegrees);
  checkPosition("the head position", settings.head.position);
  if (settings.mode == RenderMode::Conformal) checkMap(config, map);

  std::vector<int> wallIndices;
  if (settings.walls.empty()) {
    for (std::size_t i = 0; i < config.walls.size(); ++i)
      wallIndices.push_back(static_cast<int>(i));
  } else {
    for (const std::string& name : settings.walls) {
      const Wall& wall = config.wall(name);  // throws for an unknown wall, listing the known
      const int index = static_cast<int>(&wall - config.walls.data());
      if (std::find(wallIndices.begin(), wallIndices.end(), index) != wallIndices.end())
        throw Error(ErrorCode::InvalidInput, "wall '" + name + "' is requested twice");
      wallIndices.push_back(index);
    }
  }

  std::vector<std::string> wallNames;
  for (const Wall& wall : config.walls) wallNames.push_back(wall.name);
  checkViewOverrides(settings.views, wallNames);

  RenderPlan plan;
  for (int wallIndex : wallIndices) {
    const Wall& wall = config.walls[static_cast<std::size_t>(wallIndex)];
    if (!(std::max(wall.width, wall.height) * settings.resolutionScale <= kMaxOutputPixels))
      throw Error(ErrorCode::InvalidInput,
                  "resolution scale " + std::to_string(settings.resolutionScale) + " makes wall '" +
                      wall.name + "' more than " +
                      std::to_string(static_cast<int>(kMaxOutputPixels)) + " pixels wide or high");
    for (Eye eye : settings.eyes) {
      PlannedImage image;
      image.wallIndex = wallIndex;
      image.eye = eye;
      if (const ViewOverride* custom = findViewOverride(settings.views, wall.name, eye))
        image.custom = *custom;
      image.view = makeWallView(wall, image.custom ? overrideEyePosition(*image.custom)
                                                   : eyePosition(settings.head, eye,
                                                                 config.eyeSeparation));
      image.view.eye = eye;
      image.width = outputPixels(wall.width, settings.resolutionScale);
      image.height = outputPixels(wall.height, settings.resolutionScale);
      if (glm::length(image.view.eye_position - config.reference) > 1e-9)
        plan.hasOffCentreEyes = true;
      plan.images.push_back(image);
    }
  }
  return plan;
}

}  // namespace confvis
