// The code examples in the public headers' comments, extracted at build time (examples.cmake)
// and run here with the names they use bound to real objects.
#include <gtest/gtest.h>

#include <confvis/confvis.hpp>

#include <filesystem>
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

}  // namespace
