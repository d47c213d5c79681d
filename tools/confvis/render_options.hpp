#pragma once
// The options `render`, `walk` and `view` share, registered in one place so that their names,
// defaults, checks and help texts stay the same in every command (--scene-scale: scene_option.hpp).
#include <CLI/CLI.hpp>

#include <string>

namespace confvis::cli {

// The positional display config of walk and view (render's says "(JSON)").
void addDisplayConfigArgument(CLI::App& sub, std::string& config);
// --scene: a built-in scene or an OBJ/glTF file.
void addSceneOption(CLI::App& sub, std::string& scene);
// --backend: one of backendNames().
void addBackendOption(CLI::App& sub, std::string& backend);
// --scale of render and walk: output resolution as a fraction of each wall's.
void addOutputScaleOption(CLI::App& sub, double& scale);
// --radius of walk and view: how far the head may stray before the map follower re-bakes.
void addRebakeRadiusOption(CLI::App& sub, double& radius);

}  // namespace confvis::cli
