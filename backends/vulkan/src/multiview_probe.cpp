#include "multiview_probe.hpp"

#include "confvis/base/progress.hpp"

namespace confvis::vulkan {

bool multiviewKeepsClippedPrimitivesInTheirView(VulkanContext& context, Pipelines& pipelines,
                                                FrameRenderer& frames) {
  DisplayConfig config;
  config.name = "multiview probe";
  config.eyeSeparation = 0.2;
  Wall wall;
  wall.name = "probe";
  wall.lowerLeft = {-1, -1, -1};
  wall.lowerRight = {1, -1, -1};
  wall.upperLeft = {-1, 1, -1};
  wall.width = wall.height = 16;
  config.walls.push_back(wall);

  Scene scene;
  scene.name = "multiview probe";
  Mesh triangle;
  triangle.name = "covers everything";
  triangle.positions = {{-50, -50, -2}, {50, -50, -2}, {0, 50, -2}};
  triangle.normals.assign(3, glm::vec3(0, 0, 1));
  triangle.triangles = {{0, 1, 2}};
  scene.meshes.push_back(triangle);
  const GpuScene gpuScene(context, pipelines, scene);

  RenderSettings settings;
  settings.mode = RenderMode::Plain;
  settings.eyes = {Eye::Left, Eye::Right};
  const FramePlan plan = planFrame(config, nullptr, settings, {},
                                   kRequiredMultiviewViews);
  Progress silent("", 1, false);
  for (const WallImage& image : frames.render(plan, gpuScene, nullptr, true, silent))
    for (std::size_t i = 0; i < image.image.pixelCount(); ++i)
      if (image.image.pixels[4 * i + 3] != 1.0f) return false;
  return true;
}

}  // namespace confvis::vulkan
