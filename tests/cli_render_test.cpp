// End-to-end tests of `confvis render`: the files it writes (EXR per wall, multi-view stereo,
// PNG previews, overview, render.json) and what they show, conformal mode through a map
// directory, and one clear error with a non-zero exit for every kind of bad input.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

#include "confvis/backends/analytic_maps.hpp"
#include "confvis/base/atomic_file.hpp"
#include "confvis/base/cube_map.hpp"
#include "confvis/base/exr_io.hpp"
#include "confvis/base/png_io.hpp"
#include "confvis/conformal/bake_files.hpp"
#include "cli_test_support.hpp"

namespace fs = std::filesystem;

namespace {

using confvis::testing::CliRun;
using confvis::testing::runCli;
using confvis::testing::scratch;

std::string config(const std::string& name) {
  return std::string(CONFVIS_SOURCE_DIR) + "/configs/" + name + ".json";
}

// Walls of the shipped CAVEs are 1920 px: this scale gives 48 px test images.
const std::string kSmall = " --scale 0.025 -q";

// The missing ceiling's green on a side wall: green pixels in the top quarter and in the lower
// half of the image.
struct GreenBands {
  std::size_t top = 0, lower = 0;
};
GreenBands ceilingGreenBands(const confvis::ImageRGBA& wall) {
  GreenBands bands;
  for (int y = 0; y < wall.height; ++y)
    for (int x = 0; x < wall.width; ++x) {
      const float* p = wall.at(x, y);
      const bool green = p[1] > 0.8f && p[0] < 0.2f && p[2] < 0.2f;
      if (green && y < wall.height / 4) ++bands.top;
      // The floor is green too, and reaches the walls' bottom edges (the virtual forward
      // direction sits on the front wall's centre): the band below the middle, not the bottom.
      if (green && y >= wall.height / 2 && y < 3 * wall.height / 4) ++bands.lower;
    }
  return bands;
}

// Fraction of the pixels in the `size`-square at (x0, y0) (default: the whole image) that have
// colour (r, g, b).
double fractionNear(const confvis::ImageRGBA& image, float r, float g, float b, int x0 = 0,
                    int y0 = 0, int size = 0) {
  const int w = size ? size : image.width, h = size ? size : image.height;
  std::size_t n = 0;
  for (int y = y0; y < y0 + h; ++y)
    for (int x = x0; x < x0 + w; ++x) {
      const float* p = image.at(x, y);
      n += std::abs(p[0] - r) < 0.05f && std::abs(p[1] - g) < 0.05f && std::abs(p[2] - b) < 0.05f;
    }
  return static_cast<double>(n) / (static_cast<double>(w) * h);
}

double maxDifference(const confvis::ImageRGBA& a, const confvis::ImageRGBA& b,
                     std::size_t* bad = nullptr) {
  double worst = 0;
  if (bad) *bad = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    const double d = std::abs(a.pixels[i] - b.pixels[i]);
    worst = std::max(worst, d);
    if (bad && d > 0.02) ++*bad;
  }
  return worst;
}

TEST(CliRender, PlainCave6WritesEveryWallWithPreviewsOverviewAndReport) {
  const fs::path out = scratch("plain6");
  const CliRun run = runCli("render " + config("cave6") + " --mode plain -o " + out.string() + kSmall);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  for (const char* wall : {"front", "left", "right", "back", "floor", "ceiling"}) {
    SCOPED_TRACE(wall);
    const confvis::ImageRGBA image = confvis::readExr(out / (std::string(wall) + ".exr"));
    EXPECT_EQ(image.width, 48);
    const confvis::ImageRGBA preview = confvis::readPng(out / (std::string(wall) + ".png"));
    EXPECT_EQ(preview.width, 48);
    const std::string name = wall;
    const glm::vec3 face = name == "front" || name == "back"  ? glm::vec3(0, 0, 1)
                           : name == "left" || name == "right" ? glm::vec3(1, 0, 0)
                                                               : glm::vec3(0, 1, 0);
    EXPECT_GT(fractionNear(image, face.r, face.g, face.b), 0.4);
    EXPECT_GT(fractionNear(image, 1, 1, 1), 0.4);
  }
  const confvis::ImageRGBA overview = confvis::readPng(out / "overview.png");
  EXPECT_EQ(overview.width, 3 * 48);
  EXPECT_EQ(overview.height, 4 * 48);
  // Vertical cross: ceiling above the front wall, left | front | right, then floor and back.
  EXPECT_GT(fractionNear(overview, 0, 1, 0, 48, 0, 48), 0.4);   // ceiling
  EXPECT_GT(fractionNear(overview, 1, 0, 0, 0, 48, 48), 0.4);   // left
  EXPECT_GT(fractionNear(overview, 0, 0, 1, 48, 48, 48), 0.4);  // front
  EXPECT_GT(fractionNear(overview, 1, 0, 0, 96, 48, 48), 0.4);  // right
  EXPECT_GT(fractionNear(overview, 0, 1, 0, 48, 96, 48), 0.4);  // floor
  EXPECT_GT(fractionNear(overview, 0, 0, 1, 48, 144, 48), 0.4); // back
  EXPECT_EQ(fractionNear(overview, 0, 0, 0, 0, 0, 48), 1.0);    // empty corner cell
  const nlohmann::json report = nlohmann::json::parse(confvis::readTextFile(out / "render.json"));
  EXPECT_EQ(report["settings"]["mode"], "plain");
  EXPECT_EQ(report["display"]["name"], "cave6");
  EXPECT_GT(report["backend"]["rays_per_second"].get<double>(), 0.0);
  // One ray per pixel, plus the retries of rays that slipped through a shared vertex of the
  // sphere (this 48-px grid lines up with the mesh's; see EmbreeWatertight).
  EXPECT_EQ(report["backend"]["camera_rays"].get<long>() -
                report["backend"]["retraced_rays"].get<long>(),
            6 * 48 * 48);
  EXPECT_EQ(report["files"].size(), 13u);
  EXPECT_TRUE(report["timings"].contains("render_seconds"));
}

TEST(CliRender, ConformalCave6WithoutMapIsTheIdentityAndEqualsPlain) {
  const fs::path plain = scratch("c6plain"), conformal = scratch("c6conformal");
  ASSERT_EQ(runCli("render " + config("cave6") + " --mode plain -o " + plain.string() + kSmall).exitCode, 0);
  const CliRun run = runCli("render " + config("cave6") + " -o " + conformal.string() + kSmall);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  for (const char* wall : {"front", "left", "right", "back", "floor", "ceiling"}) {
    std::size_t bad = 0;
    maxDifference(confvis::readExr(plain / (std::string(wall) + ".exr")),
                  confvis::readExr(conformal / (std::string(wall) + ".exr")), &bad);
    EXPECT_LT(bad, 48u * 48u / 100) << wall;
  }
  const nlohmann::json report =
      nlohmann::json::parse(confvis::readTextFile(conformal / "render.json"));
  EXPECT_NE(report["map"].get<std::string>().find("identity"), std::string::npos);
}

TEST(CliRender, StereoWritesMultiViewExrAndSideBySidePreview) {
  const fs::path out = scratch("stereo");
  const CliRun run = runCli("render " + config("cave6") + " --eyes stereo --stereo-rays fast "
                            "--wall front --wall left --spp 2 -o " + out.string() + kSmall);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const auto [left, right] = confvis::readStereoExr(out / "front.exr");
  EXPECT_EQ(left.width, 48);
  EXPECT_EQ(right.width, 48);
  EXPECT_EQ(confvis::readPng(out / "front.png").width, 96);
  EXPECT_TRUE(fs::exists(out / "left.exr"));
  EXPECT_FALSE(fs::exists(out / "back.exr"));
  const nlohmann::json report = nlohmann::json::parse(confvis::readTextFile(out / "render.json"));
  EXPECT_EQ(report["settings"]["eyes"], nlohmann::json({"left", "right"}));
  EXPECT_EQ(report["settings"]["stereo_rays"], "fast");
  EXPECT_EQ(report["backend"]["camera_rays"].get<long>(), 2 * 2 * 2 * 48 * 48);
}

// A map directory as `confvis bake` writes it, here the analytic stand-in for a 5-sided CAVE:
// the front wall shows green (the virtual ceiling) near its top edge and none lower down.
TEST(CliRender, ConformalModeReadsABakedMapDirectory) {
  const fs::path mapDir = scratch("map5"), out = scratch("c5");
  const confvis::RetargetMap map = confvis::ceilinglessDilationMap(1.5, 64);
  confvis::writeRetargetMapDirectory(mapDir, map);  // ray.exr, geom.exr, bake.json
  const CliRun run = runCli("render " + config("cave5") + " --map " + mapDir.string() +
                            " --wall front -o " + out.string() + kSmall);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const confvis::ImageRGBA front = confvis::readExr(out / "front.exr");
  const auto [topGreen, lowerGreen] = ceilingGreenBands(front);
  EXPECT_GT(topGreen, 48u * 12u / 5u);
  EXPECT_EQ(lowerGreen, 0u);
}

// The README's main job: no arguments bake the 5-sided CAVE's map (into the cache) and render
// the checker-sphere through it; the missing ceiling's green must reach the front wall's top.
TEST(CliRender, WithoutConfigRendersTheFiveSidedCaveConformally) {
  const fs::path out = scratch("default");
  const fs::path cache = scratch("default-cache");
  ::setenv("CONFVIS_CACHE_DIR", cache.c_str(), 1);
  const CliRun run = runCli("render -o " + out.string() + kSmall);
  ::unsetenv("CONFVIS_CACHE_DIR");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const nlohmann::json report = nlohmann::json::parse(confvis::readTextFile(out / "render.json"));
  EXPECT_EQ(report["display"]["name"], "cave5");
  EXPECT_EQ(report["scene"]["name"], "checker-sphere");
  EXPECT_FALSE(fs::exists(out / "ceiling.exr"));
  EXPECT_TRUE(fs::exists(out / "floor.exr"));
  EXPECT_TRUE(fs::exists(out / "front.png"));
  EXPECT_TRUE(fs::exists(out / "overview.png"));
  EXPECT_FALSE(fs::is_empty(cache)) << "the bake was not cached";
  const confvis::ImageRGBA front = confvis::readExr(out / "front.exr");
  const auto [topGreen, lowerGreen] = ceilingGreenBands(front);
  EXPECT_GT(topGreen, static_cast<std::size_t>(front.width) * front.height / 40) << run.output;
  EXPECT_EQ(lowerGreen, 0u);
}

// `--tess-error` reaches the Vulkan backend: its report carries the threshold, and a finer one
// subdivides more of the sphere's bent edges (the ceiling-less dilation bends them).
TEST(CliRender, VulkanTessellationErrorIsTheBackendsThreshold) {
  const fs::path mapDir = scratch("map-tess");
  const confvis::RetargetMap map = confvis::ceilinglessDilationMap(1.5, 64);
  confvis::writeRetargetMapDirectory(mapDir, map);  // ray.exr, geom.exr, bake.json
  const auto tessellated = [&](const std::string& error) {
    const fs::path out = scratch("tess-" + error);
    const CliRun run = runCli("render " + config("cave5") + " --backend vulkan --map " +
                              mapDir.string() + " --wall front --tess-error " + error + " -o " +
                              out.string() + " --scale 0.1 -q");
    EXPECT_EQ(run.exitCode, 0) << run.output;
    const nlohmann::json report =
        nlohmann::json::parse(confvis::readTextFile(out / "render.json"));
    EXPECT_DOUBLE_EQ(report["backend"]["tessellation_error_pixels"].get<double>(),
                     std::stod(error));
    return report["backend"]["triangles_tessellated"].get<double>();
  };
  const double fine = tessellated("0.05"), coarse = tessellated("4");
  EXPECT_GT(fine, 2.0 * coarse + 10.0) << "fine " << fine << ", coarse " << coarse;
}

void expectError(const std::string& args, const std::string& needle) {
  const CliRun run = runCli("render " + args + kSmall);
  EXPECT_NE(run.exitCode, 0) << args;
  EXPECT_NE(run.output.find(needle), std::string::npos) << args << "\n" << run.output;
}

TEST(CliRender, BadInputGivesOneClearErrorAndNonZeroExit) {
  const std::string out = " -o " + scratch("errors").string();
  const std::string cave6 = config("cave6") + " --mode plain";
  expectError(cave6 + " --scene no-such-scene" + out, "no-such-scene");
  expectError(cave6 + " --scene /nonexistent/model.obj" + out, "/nonexistent/model.obj");
  const fs::path broken = scratch("broken.gltf");
  confvis::writeTextAtomically(broken, "{ this is not json");
  expectError(cave6 + " --scene " + broken.string() + out, "broken.gltf");
  const fs::path noTriangles = scratch("empty.obj");
  confvis::writeTextAtomically(noTriangles, "v 0 0 0\nv 1 0 0\n");
  expectError(cave6 + " --scene " + noTriangles.string() + out, "empty.obj");
  expectError(cave6 + " --wall attic" + out, "attic");
  expectError(config("cave5") + " --map /nonexistent/map" + out, "/nonexistent/map");
  expectError(cave6 + " --camera 1,2" + out, "--camera");
  expectError(cave6 + " --camera 1,2,x" + out, "--camera");
  expectError("/nonexistent/display.json" + out, "/nonexistent/display.json");
  expectError(cave6 + " --backend optix" + out, "optix");
  expectError(cave6 + " --spp 0" + out, "spp");
  expectError(cave6 + " --tess-error 0" + out, "--tess-error");
  expectError(cave6 + " --tess-error 0.5" + out, "--backend vulkan");
}

// A `confvis bake` directory carries the reference point it was baked around (bake.json): a map
// baked for a moved head must be refused for the display's own reference, not used silently.
TEST(CliRender, BakedMapOfAnotherReferencePointIsRefused) {
  const fs::path baked = scratch("baked-moved");
  const CliRun bake = runCli("bake " + config("cave5") + " -o " + baked.string() +
                             " --no-cache --resolution 32 --reference 0.3,0,0 -q");
  ASSERT_EQ(bake.exitCode, 0) << bake.output;
  const CliRun run =
      runCli("render " + config("cave5") + " --map " + baked.string() + " -o " +
             scratch("moved-out").string() + kSmall);
  EXPECT_NE(run.exitCode, 0);
  EXPECT_NE(run.output.find("baked around (0.3"), std::string::npos) << run.output;
}

TEST(CliRender, HasHelp) {
  const CliRun run = runCli("render --help");
  EXPECT_EQ(run.exitCode, 0);
  for (const char* option : {"--scene", "--mode", "--eyes", "--stereo-rays", "--wall", "--spp",
                             "--camera", "--scale", "--map", "--output", "--tess-error"})
    EXPECT_NE(run.output.find(option), std::string::npos) << option;
}

}  // namespace
