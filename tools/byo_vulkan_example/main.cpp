// confvis_byo_vulkan_example: an application with its own Vulkan renderer drawing a scene through
// the conformal map on every wall of a display (bring-your-own Vulkan, issue 25). See
// backends/vulkan/README.md, "Bring your own Vulkan renderer".
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>

#include <CLI/CLI.hpp>

#include "app_renderer.hpp"
#include "confvis/backends/render_output.hpp"
#include "confvis/backends/retarget_map_files.hpp"
#include "confvis/base/error.hpp"
#include "confvis/conformal/bake_display.hpp"
#include "confvis/engine/display_config.hpp"
#include "confvis/engine/scene_loader.hpp"

int main(int argc, char** argv) {
  CLI::App cli{
      "Renders a scene through the conformal map with the application's own Vulkan device and "
      "pipelines (confvis's bring-your-own-Vulkan helpers: map upload, per-wall bounds, the "
      "conformal pre-pass); writes WALL.exr, WALL.png and overview.png per wall."};
  std::string configPath = std::string(CONFVIS_SOURCE_DIR) + "/configs/cave5.json";
  std::string mapDirectory, sceneName = "checker-sphere", output, device;
  byo_example::AppOptions options;
  options.device = "";
  options.resolutionScale = 0.25;
  cli.add_option("config", configPath, "display config (default: configs/cave5.json)");
  cli.add_option("--map", mapDirectory,
                 "baked map directory (confvis bake); default: bake the config (cached)");
  cli.add_option("--scene", sceneName, "built-in scene name or OBJ/glTF file")
      ->capture_default_str();
  cli.add_option("--scale", options.resolutionScale, "wall resolution scale")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cli.add_option("--tess-error", options.errorPixels, "bend error bound, pixels")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cli.add_option("--device", device, "part of the Vulkan device's name (default: the first usable)");
  cli.add_flag("--validation", options.validation, "Khronos validation layer; messages to stderr");
  using Format = byo_example::AppOptions::VertexFormat;
  const std::map<std::string, Format> formats = {
      {"float32", Format::Float32}, {"half", Format::Half}, {"mixed", Format::Mixed}};
  cli.add_option("--vertex-format", options.vertexFormat,
                 "the app's own vertex buffer layout: float32 (R32 attributes), half "
                 "(R16G16B16A16_SFLOAT, R16G16_SFLOAT), mixed (R32G32B32A32_SFLOAT positions, "
                 "half normals, R16G16_UNORM uvs)")
      ->transform(CLI::CheckedTransformer(formats, CLI::ignore_case));
  cli.add_flag("--recorded-upload", options.recordedUpload,
               "record the map upload on the frame's command buffer (recordRetargetMapUpload)");
  cli.add_option("-o,--output", output, "output directory (default: out/byo-vulkan-CONFIG)");
  CLI11_PARSE(cli, argc, argv);
  try {
    options.device = device;
    options.onValidationMessage = [](const std::string& m) {
      std::fprintf(stderr, "validation: %s\n", m.c_str());
    };
    const confvis::DisplayConfig config = confvis::loadDisplayConfig(configPath);
    const confvis::Scene scene = confvis::sceneByNameOrFile(sceneName);
    std::fprintf(stderr, "map: %s\n", mapDirectory.empty() ? "baking (or from the cache)"
                                                            : mapDirectory.c_str());
    const confvis::RetargetMap map =
        mapDirectory.empty() ? confvis::bakeDisplay(config, {}).map
                             : confvis::readRetargetMapDirectory(mapDirectory);
    std::fprintf(stderr, "rendering %zu walls\n", config.walls.size());
    confvis::RenderResult result;
    result.images = byo_example::renderThroughMap(config, scene, map, options);
    const std::filesystem::path directory =
        output.empty() ? std::filesystem::path("out") / ("byo-vulkan-" + config.name)
                       : std::filesystem::path(output);
    confvis::RenderSettings settings;
    settings.resolutionScale = options.resolutionScale;
    result.stats.backend = "byo-vulkan-example";
    confvis::writeRenderOutput(directory, config, settings, result, {{"scene", sceneName}});
    std::fprintf(stderr, "wrote %s\n", directory.string().c_str());
    return 0;
  } catch (const confvis::Error& e) {
    std::fprintf(stderr, "confvis_byo_vulkan_example: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "confvis_byo_vulkan_example: unexpected error: %s\n", e.what());
    return 3;
  }
}
