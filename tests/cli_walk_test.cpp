// End-to-end test of `confvis walk`: the tunnel walked along the sample head path with real
// background bakes. The head steps away from the first map's reference point, a re-bake runs
// while frames keep coming (through the old map), the new map is swapped in around the head
// position the bake was asked for, and every frame of every map is a real image.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <glm/glm.hpp>

#include "cli_test_support.hpp"
#include "confvis/base/exr_io.hpp"

namespace fs = std::filesystem;
using confvis::testing::CliRun;
using confvis::testing::runCli;
using confvis::testing::scratch;

namespace {

glm::dvec3 vec(const nlohmann::json& v) {
  return {v.at(0).get<double>(), v.at(1).get<double>(), v.at(2).get<double>()};
}

// Fraction of pixels that are finite and not black (the tunnel's walls fill most of the view;
// only its far opening is black).
double litFraction(const confvis::ImageRGBA& image, bool* allFinite) {
  std::size_t lit = 0;
  *allFinite = true;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float* p = image.at(x, y);
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) *allFinite = false;
      lit += p[0] + p[1] + p[2] > 0.05f;
    }
  return static_cast<double>(lit) / (static_cast<double>(image.width) * image.height);
}

TEST(CliWalk, MapFollowsTheHeadWithoutStallingFrames) {
  const fs::path out = scratch("walk");
  // 32 frames at 8 fps of path time (paced, 4 s): the head leaves the 5 cm radius at t = 1.5 s
  // (frame 12), leaving 2.5 s for the first re-bake (< 1 s on a loaded 2-core machine).
  const CliRun run = runCli("walk --frames 32 --fps 8 --scale 0.02 --radius 0.05 "
                            "--bake-resolution 32 -o " + out.string());
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("re-bakes:"), std::string::npos) << run.output;

  nlohmann::json report;
  std::ifstream(out / "walk.json") >> report;
  const nlohmann::json& frames = report.at("frames");
  ASSERT_EQ(frames.size(), 32u);
  EXPECT_EQ(report.at("scene"), "checker-tunnel");

  int referenceChanges = 0, framesDuringBake = 0;
  bool bakeRunning = false;
  glm::dvec3 requested(0.0);  // head position of the bake that runs
  glm::dvec3 previous = vec(frames[0]["map"]["reference"]);
  EXPECT_LT(glm::length(previous), 1e-9) << "the first map is baked around cave5's reference";
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const nlohmann::json& frame = frames[i];
    SCOPED_TRACE("frame " + std::to_string(i));
    const glm::dvec3 reference = vec(frame["map"]["reference"]);
    const glm::dvec3 head = vec(frame["head"]["position"]);
    const bool swapped = frame["map"]["swapped"];
    if (swapped) {
      // The new map was baked around the head position where its bake started, and is used from
      // this frame on.
      ASSERT_TRUE(bakeRunning);
      EXPECT_LT(glm::length(reference - requested), 1e-9);
      EXPECT_GT(glm::length(reference - previous), 0.05);
      EXPECT_EQ(frame["map"]["generation"], frames[i - 1]["map"]["generation"].get<int>() + 1);
      bakeRunning = false;
      ++referenceChanges;
    } else {
      // Frames before the swap (a bake running or not) keep rendering through the previous map.
      EXPECT_LT(glm::length(reference - previous), 1e-12);
      if (i > 0) {
        EXPECT_EQ(frame["map"]["generation"], frames[i - 1]["map"]["generation"]);
      }
    }
    if (frame["baking"] && !frame["bake_started"] && !swapped) ++framesDuringBake;
    if (frame["bake_started"]) {
      EXPECT_FALSE(bakeRunning) << "one bake at a time";
      EXPECT_GT(frame["head_to_reference_m"].get<double>(), 0.05);
      EXPECT_TRUE(frame["baking"]);
      bakeRunning = true;
      requested = head;
    }
    previous = reference;

    // Every frame, before, during and after a re-bake, is a real image on every wall.
    const fs::path directory = out / frame["directory"].get<std::string>();
    for (const char* wall : {"front", "left", "right", "floor", "back"}) {
      ASSERT_TRUE(fs::exists(directory / (std::string(wall) + ".exr"))) << wall;
      EXPECT_TRUE(fs::exists(directory / (std::string(wall) + ".png"))) << wall;
    }
    EXPECT_TRUE(fs::exists(directory / "overview.png"));
    bool finite = false;
    const double lit = litFraction(confvis::readExr(directory / "front.exr"), &finite);
    EXPECT_TRUE(finite);
    EXPECT_GT(lit, 0.8) << "front wall mostly black";
  }
  EXPECT_GE(referenceChanges, 1) << run.output;
  // How many frames came while a bake ran depends on the machine's speed (a 20 cm bake can
  // finish within one frame), so it is recorded, not asserted; that frames never wait for a bake
  // is asserted deterministically by MapFollower's gated-bake tests.
  RecordProperty("frames_during_bake", framesDuringBake);
  EXPECT_GE(report["rebakes"]["started"].get<int>(), referenceChanges);
  EXPECT_EQ(report["rebakes"]["swapped_in"].get<int>(), referenceChanges);
  EXPECT_EQ(report["rebakes"]["failed"].get<int>(), 0);
}

TEST(CliWalk, LitFractionRejectsABlackFrame) {
  // The per-frame check above must fail for a render that produced nothing.
  confvis::ImageRGBA black(8, 8, 0.0f);
  bool finite = false;
  EXPECT_LT(litFraction(black, &finite), 0.8);
  EXPECT_TRUE(finite);
  black.at(3, 3)[0] = std::nanf("");
  litFraction(black, &finite);
  EXPECT_FALSE(finite);
}

TEST(CliWalk, MissingPathFileIsOneClearError) {
  const CliRun run = runCli("walk --path /nonexistent.csv --frames 1 --scale 0.02 -o " +
                            scratch("walk-missing").string());
  EXPECT_NE(run.exitCode, 0);
  EXPECT_NE(run.output.find("/nonexistent.csv"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(scratch("walk-missing") / "walk.json"));
}

TEST(CliWalk, HelpListsTheOptions) {
  const CliRun run = runCli("walk --help");
  EXPECT_EQ(run.exitCode, 0);
  for (const char* option : {"--path", "--scene", "--frames", "--fps", "--scale", "--radius",
                             "--backend", "--output"})
    EXPECT_NE(run.output.find(option), std::string::npos) << option;
}

}  // namespace
