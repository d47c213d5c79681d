#include "confvis/backends/render_output.hpp"

#include <algorithm>
#include <chrono>

#include "confvis/backends/render_plan.hpp"
#include "confvis/base/atomic_file.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/exr_io.hpp"
#include "confvis/base/input_limits.hpp"
#include "confvis/base/png_io.hpp"
#include "confvis/base/stopwatch.hpp"
#include "confvis/engine/version.hpp"

namespace confvis {

namespace {

const WallImage* find(const RenderResult& result, const std::string& wall, Eye eye) {
  for (const WallImage& image : result.images)
    if (image.wall == wall && image.eye == eye) return &image;
  return nullptr;
}

ImageRGBA sideBySide(const ImageRGBA& left, const ImageRGBA& right) {
  ImageRGBA out(left.width + right.width, std::max(left.height, right.height), 0.0f);
  for (int y = 0; y < left.height; ++y)
    std::copy_n(left.at(0, y), 4 * left.width, out.at(0, y));
  for (int y = 0; y < right.height; ++y)
    std::copy_n(right.at(0, y), 4 * right.width, out.at(left.width, y));
  return out;
}

nlohmann::json settingsJson(const RenderSettings& settings) {
  nlohmann::json eyes = nlohmann::json::array();
  for (Eye eye : settings.eyes) eyes.push_back(eyeName(eye));
  const glm::dvec3& head = settings.head.position;
  const glm::dquat& q = settings.head.orientation;
  const VirtualCamera& camera = settings.camera;
  return {{"mode", modeName(settings.mode)},
          {"eyes", eyes},
          {"stereo_rays", stereoRaysName(settings.stereoRays)},
          {"walls", settings.walls},
          {"samples_per_pixel", settings.samplesPerPixel},
          {"ambient_occlusion", settings.ambientOcclusion},
          {"resolution_scale", settings.resolutionScale},
          {"head", {{"position", {head.x, head.y, head.z}},
                    {"orientation_wxyz", {q.w, q.x, q.y, q.z}}}},
          {"camera", {{"position", {camera.position.x, camera.position.y, camera.position.z}},
                      {"yaw_degrees", camera.yawDegrees},
                      {"pitch_degrees", camera.pitchDegrees}}}};
}

}  // namespace

nlohmann::json writeRenderOutput(const std::filesystem::path& directory,
                                 const DisplayConfig& config, const RenderSettings& settings,
                                 const RenderResult& result, const nlohmann::json& extra) {
  if (result.images.empty())
    throw Error(ErrorCode::InvalidInput, "nothing to write: the render produced no image");
  const auto start = SteadyClock::now();
  nlohmann::json files = nlohmann::json::array();
  auto record = [&](const std::filesystem::path& name) { files.push_back(name.string()); };

  // Walls in the order their first image appears (the settings' order).
  std::vector<std::string> walls;
  for (const WallImage& image : result.images)
    if (std::find(walls.begin(), walls.end(), image.wall) == walls.end())
      walls.push_back(image.wall);
  for (const std::string& wall : walls) {
    // Wall names come from the display config: each must stay one file name inside `directory`.
    requireFileNameSafe(wall, "display '" + config.name + "': wall name");
    const WallImage* left = find(result, wall, Eye::Left);
    const WallImage* right = find(result, wall, Eye::Right);
    const WallImage* centre = find(result, wall, Eye::Center);
    const bool stereo = left && right;
    if (stereo) {
      writeStereoExr(directory / (wall + ".exr"), left->image, right->image);
      writePng(directory / (wall + ".png"), sideBySide(left->image, right->image));
      record(wall + ".exr");
      record(wall + ".png");
    }
    for (const WallImage* single : {left, centre, right}) {
      if (!single || (stereo && single != centre)) continue;
      const bool alone = (left != nullptr) + (centre != nullptr) + (right != nullptr) == 1;
      const std::string stem =
          alone && single->eye == Eye::Center ? wall : wall + "-" + eyeName(single->eye);
      writeExr(directory / (stem + ".exr"), single->image, ExrPixel::Half);
      writePng(directory / (stem + ".png"), single->image);
      record(stem + ".exr");
      record(stem + ".png");
    }
  }
  const bool hasCentre = std::any_of(result.images.begin(), result.images.end(),
                                     [](const WallImage& i) { return i.eye == Eye::Center; });
  const Eye overviewEye = hasCentre ? Eye::Center : result.images.front().eye;
  writePng(directory / "overview.png", overviewImage(config, result.images, overviewEye));
  record("overview.png");

  nlohmann::json report = {
      {"version", versionString()},
      {"display", {{"name", config.name}, {"hash", config.hash}, {"walls", config.walls.size()}}},
      {"settings", settingsJson(settings)},
      {"overview_eye", eyeName(overviewEye)},
      {"backend", toJson(result.stats)},
      {"files", files}};
  report["write_seconds"] = secondsSince(start);
  report.merge_patch(extra);
  writeTextAtomically(directory / "render.json", report.dump(2) + "\n");
  return report;
}

}  // namespace confvis
