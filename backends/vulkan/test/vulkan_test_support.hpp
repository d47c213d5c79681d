#pragma once
// Shared by the Vulkan backend tests: a lavapipe backend with validation layers whose messages
// fail the test, display configs from configs/, and per-pixel image comparison with a
// bad-pixel budget.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "confvis/backends/vulkan_backend.hpp"
#include "confvis/engine/display_config.hpp"

namespace confvis::test {

inline DisplayConfig loadConfig(const std::string& name) {
  return loadDisplayConfig(std::filesystem::path(CONFVIS_SOURCE_DIR) / "configs" / (name + ".json"));
}

// The tests always render on lavapipe (Mesa's CPU Vulkan driver, package mesa-vulkan-drivers), so
// results are the same on every machine; CI has it, so its absence is a failure, not a skip.
inline constexpr const char* kLavapipe = "llvmpipe";

// A lavapipe backend with validation layers; every message lands in `messages`.
struct ValidatedBackend {
  std::shared_ptr<std::vector<std::string>> messages = std::make_shared<std::vector<std::string>>();
  std::unique_ptr<RenderBackend> backend;

  explicit ValidatedBackend(VulkanOptions options = {}) {
    options.device = kLavapipe;
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

struct PixelComparison {
  std::size_t pixels = 0;  // compared
  std::size_t bad = 0;     // some channel off by more than the tolerance
  double maxError = 0.0;
  double badFraction() const { return pixels ? double(bad) / double(pixels) : 1.0; }
};

// Per-pixel comparison of all four channels; images of different sizes compare as all bad.
inline PixelComparison comparePixels(const ImageRGBA& a, const ImageRGBA& b, float tolerance) {
  PixelComparison c;
  c.pixels = a.pixelCount();
  if (a.width != b.width || a.height != b.height) {
    c.bad = c.pixels;
    c.maxError = 1e9;
    return c;
  }
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      double worst = 0.0;
      for (int k = 0; k < 4; ++k)
        worst = std::max(worst, double(std::abs(a.at(x, y)[k] - b.at(x, y)[k])));
      c.maxError = std::max(c.maxError, worst);
      if (worst > tolerance) ++c.bad;
    }
  return c;
}

}  // namespace confvis::test
