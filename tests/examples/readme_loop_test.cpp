// The README's frame loop (runDisplay, "Using confvis in an application") and the example in
// map_follower.hpp, as extracted from those files at build time (examples.cmake), run with both
// backends through real bakes until the map has been re-baked and swapped in three times. What
// broke before: the first swapped map was refused by the backend (baked around the head, the
// display's reference still at the centre), and the loop dereferenced an empty tracker pose.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>

#include "../../backends/vulkan/test/vulkan_test_support.hpp"
#include "readme_loop.inc"  // the README's runDisplay, verbatim

namespace {

using namespace confvis;
using Clock = std::chrono::steady_clock;

constexpr int kRebakes = 3;
// Only a loop that never swaps a map in (or hangs) gets near this.
constexpr auto kGiveUp = std::chrono::seconds(240);

// cave5 with 20-pixel walls and a coarse, small bake: a frame and a bake take a fraction of a
// second, and the loop still goes through every stage of a real one.
DisplayConfig smallCave() {
  nlohmann::json json = toJson(loadDisplayConfig(std::filesystem::path(CONFVIS_SOURCE_DIR) /
                                                 "configs" / "cave5.json"));
  json["cube_resolution"] = 32;
  json["edge_length"] = 0.5;
  for (nlohmann::json& wall : json["walls"]) wall["resolution"] = {20, 20};
  return parseDisplayConfig(json, "cave5 (small)");
}

// A head swaying 60 cm left and right, on a clock the frames advance (one 20th of a second
// each), so every run sees the same heads; silent for its first frames like a tracker that has
// not seen the head yet.
class SwayingHead : public Tracker {
 public:
  std::optional<TrackedPose> latest() override {
    if (frame_ < kSilentFrames) return std::nullopt;
    const double seconds = (frame_ - kSilentFrames) / 20.0;
    return TrackedPose{HeadPose{{0.3 * std::sin(seconds * 2.0), 0.0, 0.1}}, seconds};
  }
  void advance() { ++frame_; }
  static constexpr int kSilentFrames = 3;

 private:
  int frame_ = 0;
};

struct LoopRecord {
  int frames = 0;
  std::vector<glm::dvec3> references;  // of each generation's map, in order
  std::vector<double> drawn;           // per frame: drawn fraction of all pixels
  bool gaveUp = false;
};

LoopRecord runReadmeLoop(RenderBackend& backend) {
  const DisplayConfig display = smallCave();
  backend.setScene(builtinScene("checker-sphere"));
  SwayingHead tracker;
  LoopRecord record;
  const auto start = Clock::now();
  runDisplay(display, tracker, backend, [&](const FollowerFrame& frame, const RenderResult& images) {
    ++record.frames;
    tracker.advance();
    // The frame's display is the map's: same reference, same walls.
    EXPECT_LT(glm::length(frame.display->reference - frame.map->reference), 1e-12);
    EXPECT_EQ(frame.display->walls.size(), display.walls.size());
    if (record.references.size() <= frame.generation) record.references.push_back(frame.map->reference);
    // Both eyes of every wall, 20 x 20, drawn: the checker sphere surrounds the viewer.
    EXPECT_EQ(images.images.size(), 2 * display.walls.size());
    std::size_t drawn = 0, pixels = 0;
    for (const WallImage& wall : images.images) {
      EXPECT_EQ(wall.image.width, 20);
      EXPECT_EQ(wall.image.height, 20);
      for (int y = 0; y < wall.image.height; ++y)
        for (int x = 0; x < wall.image.width; ++x) {
          const auto& p = wall.image.at(x, y);
          EXPECT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]));
          drawn += p[3] > 0.5f;
          ++pixels;
        }
    }
    record.drawn.push_back(static_cast<double>(drawn) / static_cast<double>(pixels));
    record.gaveUp = Clock::now() - start > kGiveUp;
    return frame.generation < static_cast<std::uint64_t>(kRebakes) && !record.gaveUp &&
           !::testing::Test::HasFailure();
  });
  return record;
}

void expectThreeRebakesRendered(const LoopRecord& record) {
  ASSERT_FALSE(record.gaveUp) << "no " << kRebakes << " re-bakes in " << record.frames << " frames";
  ASSERT_EQ(record.references.size(), static_cast<std::size_t>(kRebakes + 1));
  // The first map is baked around the display's reference, each re-bake around a head that
  // strayed more than the follower's 10 cm from the map before it.
  EXPECT_LT(glm::length(record.references[0]), 1e-12);
  for (int g = 1; g <= kRebakes; ++g)
    EXPECT_GT(glm::length(record.references[g] - record.references[g - 1]), 0.1) << "map " << g;
  for (std::size_t f = 0; f < record.drawn.size(); ++f)
    EXPECT_GT(record.drawn[f], 0.95) << "frame " << f;  // measured: 0.996 at least
}

TEST(ReadmeLoop, RendersAcrossThreeRebakesWithEmbree) {
  EmbreeBackend backend;
  expectThreeRebakesRendered(runReadmeLoop(backend));
}

TEST(ReadmeLoop, RendersAcrossThreeRebakesWithVulkanOnLavapipe) {
  VulkanOptions options;
  options.device = test::testDevice();
  const std::unique_ptr<RenderBackend> backend = makeVulkanBackend(options);
  expectThreeRebakesRendered(runReadmeLoop(*backend));
}

}  // namespace
