#pragma once
// Shared by the Vulkan backend tests: a lavapipe backend with validation layers whose messages
// fail the test, display configs from configs/, and (vulkan_image_checks.hpp) per-pixel image
// comparison with a bad-pixel budget.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "confvis/backends/vulkan_backend.hpp"
#include "confvis/conformal/bake_display.hpp"
#include "confvis/engine/display_config.hpp"
#include "vulkan_image_checks.hpp"

namespace confvis::test {

inline DisplayConfig loadConfig(const std::string& name) {
  return loadDisplayConfig(std::filesystem::path(CONFVIS_SOURCE_DIR) / "configs" / (name + ".json"));
}

// `config`'s map baked afresh (not from a cache another test or run may have left) at cube face
// size `resolution`, with the defaults otherwise.
inline RetargetMap bakeUncached(const DisplayConfig& config, int resolution) {
  BakeDisplayOptions options;
  options.useCache = false;
  options.resolution = resolution;
  return bakeDisplay(config, options).map;
}

// The tests always render on lavapipe (Mesa's CPU Vulkan driver, package mesa-vulkan-drivers), so
// results are the same on every machine; CI has it, so its absence is a failure, not a skip.
inline constexpr const char* kLavapipe = "llvmpipe";

// The device the rendering tests use: lavapipe, or by hand CONFVIS_TEST_VULKAN_DEVICE (a name part
// or an index, as --device takes), to check that a real GPU passes the same comparisons.
inline std::string testDevice() {
  const char* chosen = std::getenv("CONFVIS_TEST_VULKAN_DEVICE");
  return chosen && *chosen ? chosen : kLavapipe;
}

// A lavapipe backend with validation layers; every message lands in `messages`.
struct ValidatedBackend {
  std::shared_ptr<std::vector<std::string>> messages = std::make_shared<std::vector<std::string>>();
  std::unique_ptr<RenderBackend> backend;

  explicit ValidatedBackend(VulkanOptions options = {}) {
    options.device = testDevice();
    options.validation = true;
    auto sink = messages;
    options.onValidationMessage = [sink](const std::string& m) { sink->push_back(m); };
    backend = makeVulkanBackend(options);
  }
  RenderBackend* operator->() { return backend.get(); }
};

// Fails the current test for every validation message collected so far.
inline void expectNoValidationMessages(const ValidatedBackend& b) {
  EXPECT_TRUE(b.messages->empty()) << b.messages->size() << " validation message(s), first: "
                                   << (b.messages->empty() ? "" : b.messages->front());
}

// Walls rendered about `pixels` wide: scale for a wall `width` pixels wide.
inline double scaleFor(const DisplayConfig& config, int pixels) {
  return static_cast<double>(pixels) / config.walls.front().width;
}

inline const WallImage& imageOf(const RenderResult& result, const std::string& wall,
                                Eye eye = Eye::Center) {
  for (const WallImage& image : result.images)
    if (image.wall == wall && image.eye == eye) return image;
  throw std::runtime_error("no image for wall " + wall);
}

}  // namespace confvis::test
