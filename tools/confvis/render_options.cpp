#include "render_options.hpp"

#include "backend_factory.hpp"
#include "command.hpp"

namespace confvis::cli {

void addDisplayConfigArgument(CLI::App& sub, std::string& config) {
  sub.add_option("config", config, "Display config; default: configs/cave5.json");
}

void addSceneOption(CLI::App& sub, std::string& scene) {
  sub.add_option("--scene", scene,
                 "Built-in scene (checker-sphere, checker-tunnel, graph) or an OBJ/glTF file")
      ->capture_default_str();
}

void addBackendOption(CLI::App& sub, std::string& backend) {
  sub.add_option("--backend", backend, "Renderer")
      ->check(CLI::IsMember(backendNames()))
      ->capture_default_str();
}

void addOutputScaleOption(CLI::App& sub, double& scale) {
  sub.add_option("--scale", scale, "Output resolution as a fraction of each wall's")
      ->check(kPositiveNumber)
      ->capture_default_str();
}

void addRebakeRadiusOption(CLI::App& sub, double& radius) {
  sub.add_option("--radius", radius,
                 "Metres the head may stray from the map's reference before a re-bake")
      ->check(kPositiveNumber)
      ->capture_default_str();
}

}  // namespace confvis::cli
