#pragma once
// The two-frame case the once-a-frame capture (vulkan_warp_once_test.cpp) and the per-wall flat
// cull (vulkan_flat_wall_cull_test.cpp) are checked on: cave5's baked map, bent triangles and
// torn pieces at its cut on several walls, both eyes in one multiview pass, then the frame with
// the head moved, which reuses the pre-pass and the capture.
#include <utility>

#include "confvis/engine/builtin_scenes.hpp"
#include "vulkan_test_support.hpp"

namespace confvis::test {

struct TwoFrames {
  DisplayConfig config = loadConfig("cave5");
  RetargetMap map = bakeUncached(config, 64);
  Scene scene;
  RenderSettings settings;
  RenderSettings moved;  // the next frame: the head moved, the pre-pass reused

  TwoFrames() {
    BuiltinSceneOptions sceneOptions;
    sceneOptions.subdivision = 40;  // 19k triangles
    scene = builtinScene("checker-sphere", sceneOptions);
    settings.mode = RenderMode::Conformal;
    settings.resolutionScale = scaleFor(config, 128);
    settings.eyes = {Eye::Left, Eye::Right};
    settings.head.position = glm::dvec3(0.1, 0.05, 0.1);
    moved = settings;
    moved.head.position = glm::dvec3(-0.2, 0.0, 0.15);
  }

  // Both frames on a lavapipe backend with validation and `options`: no message, and the second
  // frame reuses the pre-pass.
  std::pair<RenderResult, RenderResult> render(const VulkanOptions& options) const {
    ValidatedBackend vk(options);
    vk->setScene(scene);
    std::pair<RenderResult, RenderResult> results{vk->render(config, &map, settings),
                                                  vk->render(config, &map, moved)};
    EXPECT_TRUE(results.second.stats.vulkan.value().conformalPrepass.value().prepassReused);
    expectNoValidationMessages(vk);
    return results;
  }
};

}  // namespace confvis::test
