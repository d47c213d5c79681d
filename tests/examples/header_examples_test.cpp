// The code examples in the public headers' comments, extracted at build time (examples.cmake)
// and run here with the names they use bound to real objects.
#include <gtest/gtest.h>

#include "../public_headers.hpp"

#include <confvis/confvis.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <vector>

namespace {

using namespace confvis;

// map_follower.hpp's loop: Embree renders 12-pixel walls for `frames` frames while a recorded
// head path steps 30 cm aside; the bake is a stand-in (identity maps), so the loop swaps maps
// within a few frames.
MapFollowerStats runMapFollowerExample(int frames, std::vector<std::string>& logged) {
  const DisplayConfig config = loadDisplayConfig(std::filesystem::path(CONFVIS_SOURCE_DIR) /
                                                 "configs" / "cave5.json");
  const BakeFunction bake = [](const DisplayConfig&, const glm::dvec3& reference) {
    return RetargetMap::identity(8, reference);
  };
  int framesRun = 0;
  RecordedPathTracker tracker(
      RecordedPath({PathKey{0.0, HeadPose{{0, 0, 0}}}, PathKey{1.0, HeadPose{{0.3, 0, 0}}}}),
      /*loop=*/false, [&] { return framesRun / 10.0; });
  EmbreeBackend backend;
  backend.setScene(builtinScene("checker-sphere"));
  RenderSettings settings;
  settings.resolutionScale = 12.0 / config.walls.front().width;
  RenderResult images;
  const auto log = [&](const std::string& error) { logged.push_back(error); };
  MapFollowerStats stats;
  const auto running = [&] { return ++framesRun <= frames; };
  {
#include "map_follower_loop.inc"
    follower.waitForBake();
    stats = follower.stats();
    EXPECT_EQ(images.images.size(), config.walls.size());
  }
  return stats;
}

TEST(HeaderExamples, MapFollowerLoopRendersThroughItsSwappedMaps) {
  std::vector<std::string> logged;
  const MapFollowerStats stats = runMapFollowerExample(40, logged);
  EXPECT_TRUE(logged.empty()) << logged.front();
  EXPECT_GE(stats.bakesSucceeded, 1);
  EXPECT_EQ(stats.bakesFailed, 0);
}

// cave5 with a coarse, small bake, so that three real bakes take a fraction of a second.
DisplayConfig coarseCave() {
  nlohmann::json json = toJson(loadDisplayConfig(std::filesystem::path(CONFVIS_SOURCE_DIR) /
                                                 "configs" / "cave5.json"));
  json["cube_resolution"] = 16;
  json["edge_length"] = 0.5;
  return parseDisplayConfig(json, "cave5 (coarse)");
}

TEST(HeaderExamples, BackgroundBakeMakesFollowersOnAnyThreadCount) {
  const DisplayConfig display = coarseCave();
#include "background_bake.inc"
  for (MapFollower* each : {&follower, &gentle, &greedy}) {
    const FollowerFrame frame = each->beginFrame(HeadPose{});
    EXPECT_EQ(frame.map->resolution(), 16);
    EXPECT_LT(glm::length(frame.map->reference - display.reference), 1e-12);
  }
}

TEST(HeaderExamples, FrameStatsReadsTheFrameJustRendered) {
  const DisplayConfig display = loadDisplayConfig(std::filesystem::path(CONFVIS_SOURCE_DIR) /
                                                  "configs" / "cave5.json");
  EmbreeBackend backend;
  backend.setScene(builtinScene("checker-sphere"));
  RenderSettings settings;
  settings.resolutionScale = 8.0 / display.walls.front().width;
  const RetargetMap map = RetargetMap::identity(8, display.reference);
  std::vector<std::string> shown;
  const auto overlay = [&](const char* format, double value) {
    char line[64];
    std::snprintf(line, sizeof line, format, value);
    shown.emplace_back(line);
  };
#include "frame_stats.inc"
  EXPECT_EQ(stats.backend, "embree");
  ASSERT_EQ(shown.size(), 1u);
  EXPECT_NE(shown[0].find(" ms"), std::string::npos);
}

// A marker `example: NAME` in a public header (or the README) whose example examples.cmake does
// not extract would be an example nobody compiles.
TEST(HeaderExamples, EveryMarkedExampleIsExtractedByTheBuild) {
  const std::filesystem::path root = CONFVIS_SOURCE_DIR;
  std::ifstream cmake(root / "tests/examples/examples.cmake");
  ASSERT_TRUE(cmake);
  const std::string registered((std::istreambuf_iterator<char>(cmake)), {});
  const std::regex marker(R"re((?:^// |<!-- )example: ([a-z0-9_]+))re");
  int markers = 0;
  std::vector<std::filesystem::path> files{root / "README.md"};
  for (const std::filesystem::path& header : confvis::test::publicHeaders())
    files.push_back(header);
  for (const std::filesystem::path& file : files) {
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);) {
      std::smatch match;
      if (!std::regex_search(line, match, marker)) continue;
      ++markers;
      EXPECT_NE(registered.find("confvis_example(" + match[1].str()), std::string::npos)
          << file << ": example " << match[1] << " is not in tests/examples/examples.cmake";
    }
  }
  EXPECT_GE(markers, 5);  // readme_loop, readme_main, map_follower_loop, background_bake, ...
}

}  // namespace
