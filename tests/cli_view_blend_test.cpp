// `confvis view` on a projection wall (configs/imported/sgct-projectors2.xml: two overlapping
// projectors and a preview window) with the config's "edge_blend": each projector's presented
// frame is ramped in its signal exactly as `confvis render` ramps it (display_surfaces.hpp,
// EdgeBlender): checked in the screenshots against the closed form, and a wrong gamma fails.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <string>

#include "cli_test_support.hpp"
#include "confvis/base/atomic_file.hpp"
#include "confvis/base/png_io.hpp"
#include "projector_sample.hpp"
#include "screenshot_compare.hpp"
#include "view_test_support.hpp"

namespace fs = std::filesystem;
using confvis::testing::CliRun;
using confvis::testing::leftProjectorWeight;
using confvis::testing::importedProjectorConfig;
using confvis::testing::runCli;
using confvis::testing::scratch;
using confvis::testing::VirtualDisplay;

namespace {

// Pixels of the left projector's blended screenshot (8-bit sRGB codes) that differ from the
// plain one's codes scaled by weight^(1/gamma) by more than the screenshots' tolerance.
int badPixels(const confvis::ImageRGBA& plain, const confvis::ImageRGBA& blended, double gamma) {
  int bad = 0;
  for (int y = 0; y < plain.height; ++y)
    for (int x = 0; x < plain.width; ++x) {
      const double factor = std::pow(leftProjectorWeight(x, plain.width), 1 / gamma);
      for (int c = 0; c < 3; ++c) {
        const double expected = plain.at(x, y)[c] * 255.0 * factor;
        if (std::abs(blended.at(x, y)[c] * 255.0 - expected) >
            confvis::testing::kScreenshotTolerance + 0.01) {
          ++bad;
          break;
        }
      }
    }
  return bad;
}

void expectViewBlends(const std::string& backend) {
  if (VirtualDisplay::shared().name().empty()) GTEST_SKIP() << VirtualDisplay::shared().whyUnavailable();
  const fs::path plainConfig = importedProjectorConfig("view-projectors-plain", "");
  const fs::path blendConfig = importedProjectorConfig("view-projectors-blend", " --edge-blend 2.2");
  const std::string common = " --backend " + backend +
                             " --frames 2 --scale 0.05 --bake-resolution 32 --no-vsync -q";
  const fs::path plain = scratch("view-blend-plain-" + backend),
                 blended = scratch("view-blend-" + backend);
  for (const auto& [config, out] : {std::pair{plainConfig, plain}, std::pair{blendConfig, blended}}) {
    const CliRun run = runCli("view " + config.string() + common + " --screenshot-dir " +
                                  (out / "shots").string() + " -o " + out.string(),
                              VirtualDisplay::shared().environment());
    ASSERT_EQ(run.exitCode, 0) << run.output;
  }
  const nlohmann::json report = nlohmann::json::parse(confvis::readTextFile(blended / "view.json"));
  EXPECT_EQ(report.at("edge_blend"), true);
  // The blend is applied on the CPU: Vulkan frames of blended walls take the staging path.
  EXPECT_EQ(report.at("frame_path"), "staging");
  EXPECT_EQ(nlohmann::json::parse(confvis::readTextFile(plain / "view.json")).at("edge_blend"),
            false);

  const confvis::ImageRGBA before =
      confvis::readPng(plain / "shots/projector-left.png", confvis::PngDecoding::Raw);
  const confvis::ImageRGBA after =
      confvis::readPng(blended / "shots/projector-left.png", confvis::PngDecoding::Raw);
  ASSERT_EQ(before.width, 96);
  ASSERT_EQ(after.width, before.width);
  ASSERT_EQ(after.height, before.height);
  // The scene shows in the overlap (columns 80..95), else the comparison proves nothing.
  int lit = 0;
  for (int y = 0; y < before.height; ++y)
    for (int x = 80; x < before.width; ++x) {
      const float* p = before.at(x, y);
      lit += p[0] + p[1] + p[2] > 0.3f;
    }
  ASSERT_GT(lit, before.height * 16 / 2);
  EXPECT_LE(badPixels(before, after, 2.2), before.pixelCount() * confvis::testing::kScreenshotBadBudget);
  // Broken on purpose: a linear ramp in the signal (gamma 1) is not what was presented.
  EXPECT_GT(badPixels(before, after, 1.0), lit / 2);
  // The preview is no projector: presented as rendered (Vulkan's plain run took the GPU path,
  // the blended one the staging path: equal within the screenshots' tolerance).
  EXPECT_LE(confvis::testing::badPixelFraction(plain / "shots/preview.png",
                                               blended / "shots/preview.png"),
            confvis::testing::kScreenshotBadBudget);
}

}  // namespace

TEST(CliViewBlend, EmbreeProjectorScreenshotsAreBlendedAsRendered) { expectViewBlends("embree"); }

TEST(CliViewBlend, VulkanProjectorScreenshotsAreBlendedAsRendered) { expectViewBlends("vulkan"); }
