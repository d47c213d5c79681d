#pragma once
// --scene and --scene-scale, shared by render and walk.
#include <CLI/CLI.hpp>

#include <string>

#include "confvis/engine/display_config.hpp"
#include "confvis/engine/scene.hpp"

namespace confvis::cli {

void addSceneScaleOption(CLI::App& sub, double& sceneScale);

// sceneByNameOrFile, positions multiplied by `sceneScale`; warns (stderr) when the scene is far
// larger than `display`, as a model in millimetres read as metres is (scene_units.hpp).
Scene loadSceneInUnits(const std::string& nameOrFile, double sceneScale,
                       const DisplayConfig& display);

}  // namespace confvis::cli
