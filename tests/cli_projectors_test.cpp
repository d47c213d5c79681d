// A projection wall as labs write it for SGCT (configs/imported/sgct-projectors2.xml: two
// overlapping projectors and a master preview window) imports, renders every window, and with
// --edge-blend each projector's overlap is ramped in its signal exactly as display_surfaces.hpp
// says.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "projector_sample.hpp"
#include "confvis/base/atomic_file.hpp"
#include "confvis/base/exr_io.hpp"
#include "confvis/base/png_io.hpp"
#include "confvis/engine/display_config.hpp"

namespace fs = std::filesystem;
using confvis::testing::CliRun;
using confvis::testing::leftProjectorWeight;
using confvis::testing::runCli;
using confvis::testing::scratch;

namespace {

const std::string kSample =
    (fs::path(CONFVIS_SOURCE_DIR) / "configs/imported/sgct-projectors2.xml").string();

// Pixels of the left projector whose blended colour differs from the plain one ramped by
// weight^(1/gamma) in the sRGB signal (tolerance: half floats in the EXR).
int badPixels(const confvis::ImageRGBA& plain, const confvis::ImageRGBA& blended, double gamma) {
  int bad = 0;
  for (int y = 0; y < plain.height; ++y)
    for (int x = 0; x < plain.width; ++x) {
      const float factor = static_cast<float>(std::pow(leftProjectorWeight(x, plain.width), 1 / gamma));
      for (int c = 0; c < 4; ++c) {
        const float p = plain.at(x, y)[c];
        const float expected =
            c == 3 ? p : confvis::srgbToLinear(confvis::linearToSrgb(p) * factor);
        if (std::abs(blended.at(x, y)[c] - expected) > 2e-3f * std::max(1.0f, std::abs(expected)) + 1e-4f) {
          ++bad;
          break;
        }
      }
    }
  return bad;
}

TEST(CliProjectors, SgctProjectorWallImportsRendersAndBlends) {
  const fs::path cache = scratch("projectors-cache");
  const std::string env = "CONFVIS_CACHE_DIR=" + cache.string();
  const fs::path plainConfig = scratch("projectors-plain.json");
  const fs::path blendConfig = scratch("projectors-blend.json");
  const CliRun imported = runCli("import " + kSample + " -o " + plainConfig.string());
  ASSERT_EQ(imported.exitCode, 0) << imported.output;
  EXPECT_NE(imported.output.find("imported as a preview window"), std::string::npos)
      << imported.output;
  ASSERT_EQ(runCli("import " + kSample + " --edge-blend 2.2 -o " + blendConfig.string()).exitCode, 0);
  EXPECT_TRUE(confvis::loadDisplayConfig(blendConfig).edgeBlend.enabled);
  for (const fs::path& file : {plainConfig, blendConfig}) {  // a quick map: small cube maps
    nlohmann::json json = nlohmann::json::parse(confvis::readTextFile(file));
    json["cube_resolution"] = 64;
    json["edge_length"] = 0.3;
    std::ofstream(file) << json.dump(2);
  }

  const fs::path plain = scratch("projectors-plain"), blended = scratch("projectors-blend");
  const CliRun first = runCli("render " + plainConfig.string() + " --scale 0.025 -q -o " + plain.string(), env);
  ASSERT_EQ(first.exitCode, 0) << first.output;
  const CliRun second = runCli("render " + blendConfig.string() + " --scale 0.025 -q -o " + blended.string(), env);
  ASSERT_EQ(second.exitCode, 0) << second.output;

  // Every window rendered its part: both projectors and the preview.
  for (const char* wall : {"preview", "projector-left", "projector-right"}) {
    EXPECT_TRUE(fs::exists(plain / (std::string(wall) + ".exr"))) << wall;
    EXPECT_TRUE(fs::exists(blended / (std::string(wall) + ".png"))) << wall;
  }
  const confvis::ImageRGBA before = confvis::readExr(plain / "projector-left.exr");
  const confvis::ImageRGBA after = confvis::readExr(blended / "projector-left.exr");
  ASSERT_EQ(before.width, 48);
  ASSERT_EQ(after.width, before.width);
  ASSERT_EQ(after.height, before.height);
  // The scene shows in the overlap (columns 40..47) (else the comparison proves nothing).
  int lit = 0;
  for (int y = 0; y < before.height; ++y)
    for (int x = 40; x < before.width; ++x) {
      const float* p = before.at(x, y);
      lit += p[0] + p[1] + p[2] > 0.05f;
    }
  ASSERT_GT(lit, before.height * 8 / 2);
  EXPECT_EQ(badPixels(before, after, 2.2), 0);
  // Broken on purpose: a linear ramp in the signal (gamma 1) is not what was applied.
  EXPECT_GT(badPixels(before, after, 1.0), lit / 2);
  // The preview is no projector: left as rendered.
  const confvis::ImageRGBA previewBefore = confvis::readExr(plain / "preview.exr");
  const confvis::ImageRGBA previewAfter = confvis::readExr(blended / "preview.exr");
  EXPECT_EQ(previewBefore.pixels, previewAfter.pixels);
}

}  // namespace
