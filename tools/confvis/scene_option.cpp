#include "scene_option.hpp"

#include <cstdio>

#include "command.hpp"
#include "confvis/engine/scene_loader.hpp"
#include "confvis/engine/scene_units.hpp"

namespace confvis::cli {

void addSceneScaleOption(CLI::App& sub, double& sceneScale) {
  sub.add_option("--scene-scale", sceneScale,
                 "Multiply the scene's coordinates by this (0.001: a model in millimetres)")
      ->check(kPositiveNumber)
      ->capture_default_str();
}

Scene loadSceneInUnits(const std::string& nameOrFile, double sceneScale,
                       const DisplayConfig& display) {
  Scene scene = sceneByNameOrFile(nameOrFile);
  if (sceneScale != 1.0) scaleScene(scene, sceneScale);
  if (const auto hint = sceneUnitsHint(scene, display))
    std::fprintf(stderr, "confvis: warning: %s\n", hint->c_str());
  return scene;
}

}  // namespace confvis::cli
