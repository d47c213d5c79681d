// End-to-end tests of `confvis view` on an X display (Xvfb when DISPLAY is unset; skipped only
// where no Xvfb is installed): presented frames read back from the swapchain equal the offline
// render of the same frame, closing a window ends the program with exit 0, resizing one
// recreates its swapchain without a validation message, and a re-bake in the background holds
// no frame up.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "bake_holdup.hpp"
#include "cli_test_support.hpp"
#include "confvis/base/atomic_file.hpp"
#include "confvis/base/png_io.hpp"
#include "screenshot_compare.hpp"
#include "view_test_support.hpp"

namespace fs = std::filesystem;
using confvis::testing::badPixelFraction;
using confvis::testing::CliRun;
using confvis::testing::runCli;
using confvis::testing::scratch;
using confvis::testing::VirtualDisplay;

namespace {

std::string config(const std::string& name) {
  return std::string(CONFVIS_SOURCE_DIR) + "/configs/" + name + ".json";
}

#define REQUIRE_DISPLAY()                                    \
  if (VirtualDisplay::shared().name().empty()) {             \
    GTEST_SKIP() << VirtualDisplay::shared().whyUnavailable(); \
  }

CliRun runView(const std::string& args) {
  return runCli("view " + args + " -q", VirtualDisplay::shared().environment());
}

nlohmann::json readReport(const fs::path& directory) {
  return nlohmann::json::parse(confvis::readTextFile(directory / "view.json"));
}

constexpr int kTolerance = confvis::testing::kScreenshotTolerance;
constexpr double kBadBudget = confvis::testing::kScreenshotBadBudget;
const std::string kScale = " --scale 0.05";  // 96 x 96 pixels per wall of cave6

// The view's screenshots against `confvis render` of the same frame, and against a render from
// a camera 20 cm to the side, which must fail the same check. Mono runs present without vsync
// (lavapipe's X11 surfaces offer MAILBOX and IMMEDIATE), stereo runs with FIFO.
void expectScreenshotsMatchRender(const std::string& backend, const std::string& eyes) {
  const std::string name = backend + "-" + eyes;
  const fs::path shots = scratch("view-shots-" + name), view = scratch("view-" + name);
  const fs::path same = scratch("view-render-" + name), moved = scratch("view-moved-" + name);
  const std::string common = config("cave6") + " --backend " + backend + " --eyes " + eyes + kScale;
  const bool vsync = eyes == "stereo";
  const CliRun run = runView(common + " --frames 3 --screenshot-dir " + shots.string() + " -o " +
                             view.string() + (vsync ? "" : " --no-vsync"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  ASSERT_EQ(runCli("render " + common + " -q -o " + same.string()).exitCode, 0);
  ASSERT_EQ(runCli("render " + common + " --camera 0.2,0,0 -q -o " + moved.string()).exitCode, 0);

  const nlohmann::json report = readReport(view);
  EXPECT_EQ(report["frame_count"], 3);
  EXPECT_EQ(report["end"], "frames");
  // Vulkan frames stay on the presenting device (one blit into the swapchain image each).
  EXPECT_EQ(report["frame_path"], backend == "vulkan" ? "gpu" : "staging");
  ASSERT_EQ(report["windows"].size(), 6u);
  for (const nlohmann::json& window : report["windows"]) {
    const std::string wall = window["wall"];
    SCOPED_TRACE(wall);
    const int width = eyes == "stereo" ? 192 : 96;
    EXPECT_EQ(window["swapchain"], nlohmann::json({width, 96}));
    EXPECT_EQ(window["stereo_output"], eyes == "stereo" ? "side-by-side" : "mono");
    if (vsync) {
      EXPECT_EQ(window["present_mode"], "fifo");
    } else {
      EXPECT_NE(window["present_mode"], "fifo");
    }
    ASSERT_EQ(window["screenshot"], wall + ".png");
    EXPECT_LE(badPixelFraction(shots / (wall + ".png"), same / (wall + ".png"), kTolerance),
              kBadBudget);
    // The walls that see the sphere move with the camera; the check must catch that.
    if (wall == "front" || wall == "left" || wall == "right" || wall == "back") {
      EXPECT_GT(badPixelFraction(shots / (wall + ".png"), moved / (wall + ".png"), kTolerance),
                kBadBudget);
    }
  }
}

}  // namespace

TEST(CliView, EmbreeMonoScreenshotIsTheOfflineRender) {
  REQUIRE_DISPLAY();
  expectScreenshotsMatchRender("embree", "mono");
}

TEST(CliView, EmbreeSideBySideStereoScreenshotIsTheOfflineRender) {
  REQUIRE_DISPLAY();
  expectScreenshotsMatchRender("embree", "stereo");
}

TEST(CliView, VulkanMonoScreenshotIsTheOfflineRender) {
  REQUIRE_DISPLAY();
  expectScreenshotsMatchRender("vulkan", "mono");
}

TEST(CliView, VulkanSideBySideStereoScreenshotIsTheOfflineRender) {
  REQUIRE_DISPLAY();
  expectScreenshotsMatchRender("vulkan", "stereo");
}

// A window manager's resize and close, sent from outside: the swapchain is recreated at the
// new size, the validation layer reports nothing, and closing ends the program with exit 0.
TEST(CliView, ResizeRecreatesTheSwapchainAndCloseEndsCleanly) {
  REQUIRE_DISPLAY();
  const fs::path out = scratch("view-close"), log = scratch("view-close.log");
  const pid_t pid = confvis::testing::startBackground(
      "env " + VirtualDisplay::shared().environment() + " " + CONFVIS_CLI_PATH + " view " +
          config("cave6") + kScale + " --validate -q -o " + out.string(),
      log);
  Display* display = XOpenDisplay(VirtualDisplay::shared().name().c_str());
  ASSERT_NE(display, nullptr);
  const auto window = confvis::testing::waitForWindow(display, "confvis view: front", 30.0);
  ASSERT_TRUE(window) << "no window appeared: " << confvis::readTextFile(log);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // a few frames at the first size
  XResizeWindow(display, *window, 160, 120);
  XFlush(display);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // frames at the new size
  confvis::testing::requestClose(display, *window);
  const std::optional<int> exitCode = confvis::testing::waitExit(pid, 60.0);
  XCloseDisplay(display);
  ASSERT_TRUE(exitCode) << "still running after the close: " << confvis::readTextFile(log);
  EXPECT_EQ(*exitCode, 0) << confvis::readTextFile(log);

  const nlohmann::json report = readReport(out);
  EXPECT_EQ(report["end"], "window closed");
  EXPECT_GT(report["frame_count"].get<int>(), 2);
  EXPECT_TRUE(report["validation"]["enabled"].get<bool>());
  EXPECT_EQ(report["validation"]["errors"], 0) << report["validation"].dump(2);
  EXPECT_EQ(report["validation"]["warnings"], 0) << report["validation"].dump(2);
  for (const nlohmann::json& entry : report["windows"]) {
    SCOPED_TRACE(entry["wall"].get<std::string>());
    if (entry["wall"] == "front") {
      EXPECT_GE(entry["swapchain_recreations"].get<int>(), 1);
      EXPECT_EQ(entry["swapchain"], nlohmann::json({160, 120}));
    } else {
      EXPECT_EQ(entry["swapchain_recreations"], 0);
      EXPECT_EQ(entry["swapchain"], nlohmann::json({96, 96}));
    }
  }
}

namespace {

// The frame number and map state of `view`'s progress lines ("view: frame N, ... map G[ (re-baking)],
// ..."): the first frame seen with a swapped-in map and no bake running, and the latest frame.
struct ProgressSeen {
  int latest = -1, settledAt = -1;
};

ProgressSeen readProgress(const fs::path& log) {
  ProgressSeen seen;
  std::istringstream lines(confvis::readTextFile(log));
  for (std::string line; std::getline(lines, line);) {
    int frame = 0;
    unsigned long long generation = 0;
    const std::size_t map = line.find(", map ");
    if (std::sscanf(line.c_str(), "view: frame %d,", &frame) != 1 || map == std::string::npos ||
        std::sscanf(line.c_str() + map, ", map %llu", &generation) != 1)
      continue;
    seen.latest = frame;
    if (seen.settledAt < 0 && generation >= 1 && line.find("re-baking") == std::string::npos)
      seen.settledAt = frame;
  }
  return seen;
}

}  // namespace

// The head steps 30 cm (a pose sent over UDP once the frames are going): the map follower
// re-bakes in the background while frames keep coming through the old map, and the new one is
// swapped in. A frame that waited for the bake would last as long as the bake; so no frame from
// the one that starts it to the one that swaps its map in (the renderer prepares its per-map
// tables there) may take 3/4 of that span, nor be slower than both 10 x the p99 of the frames
// without a bake + 400 ms and 1.5 x the slowest of them (bake_holdup.hpp: bounds relative to
// the same run, so a loaded machine, where every frame is slow, passes, and a waiting render
// fails however loaded: tests/bake_holdup_test.cpp). The run goes on until its progress lines
// show 150 frames after the swap, so a slow machine gets as many frames without a bake as a
// quick one; then its window is closed.
TEST(CliView, ReBakeInTheBackgroundHoldsNoFrameUp) {
  REQUIRE_DISPLAY();
  const fs::path out = scratch("view-rebake"), log = scratch("view-rebake.log");
  const int port = confvis::testing::freeUdpPort();
  Display* display = XOpenDisplay(VirtualDisplay::shared().name().c_str());
  ASSERT_NE(display, nullptr);
  const pid_t pid = confvis::testing::startBackground(
      "env " + VirtualDisplay::shared().environment() + " " + CONFVIS_CLI_PATH + " view " +
          config("cave5") + " --tracker udp:" + std::to_string(port) +
          " --bake-resolution 64 --scale 0.02 -o " + out.string(),
      log);
  const auto window = confvis::testing::waitForWindow(display, "confvis view: front", 60.0);
  ASSERT_TRUE(window) << "no window appeared: " << confvis::readTextFile(log);
  constexpr int kFramesBefore = 30, kFramesAfterSwap = 150;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(240);
  ProgressSeen seen;
  bool moved = false;
  while (std::chrono::steady_clock::now() < deadline) {
    seen = readProgress(log);
    if (!moved && seen.latest >= kFramesBefore) {
      for (int i = 0; i < 5; ++i)  // a few times: UDP may drop one
        confvis::testing::sendTo(port, "{\"t\": 1, \"pos\": [0.3, 0, 0], \"quat\": [0, 0, 0, 1]}\n");
      moved = true;
    }
    if (seen.settledAt >= 0 && seen.latest >= seen.settledAt + kFramesAfterSwap) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  confvis::testing::requestClose(display, *window);
  const std::optional<int> exitCode = confvis::testing::waitExit(pid, 60.0);
  XCloseDisplay(display);
  ASSERT_TRUE(exitCode) << "still running after the close: " << confvis::readTextFile(log);
  ASSERT_EQ(*exitCode, 0) << confvis::readTextFile(log);
  EXPECT_GE(seen.settledAt, 0) << "no swapped map within 240 s: " << confvis::readTextFile(log);

  const nlohmann::json report = readReport(out);
  ASSERT_GE(report["rebakes"]["started"].get<int>(), 1) << report["rebakes"].dump();
  EXPECT_GE(report["rebakes"]["swapped"].get<int>(), 1) << report["rebakes"].dump();
  EXPECT_EQ(report["rebakes"]["failed"], 0);
  const nlohmann::json& frames = report["frames"];
  const confvis::testing::BakeHoldup m = confvis::testing::measureBakeHoldup(frames);
  std::printf("[ measured ] %d frames without a bake: p50 %.2f ms, p99 %.2f ms; the bake: %.0f ms "
              "over %d frames from its start to its swap, worst %.2f ms\n",
              m.calmFrames, m.calmP50Ms, m.calmP99Ms, m.bakeMs, m.bakingFrames, m.worstBakingMs);
  for (const std::string& problem : confvis::testing::bakeHoldupProblems(m, 100))
    ADD_FAILURE() << problem;
  // The log says when the map changed: generation 1 from the first swapped frame on.
  ASSERT_GE(m.swappedAt, 1);
  EXPECT_EQ(frames[m.swappedAt - 1]["map_generation"], 0);
  EXPECT_EQ(frames[m.swappedAt]["map_generation"], 1);
  EXPECT_TRUE(frames[m.swappedAt - 1]["bake_in_flight"].get<bool>());
}

TEST(CliView, NoDisplayOrBadPlacementIsOneClearError) {
  // Without any display: one error naming what is missing, exit 2.
  const CliRun noDisplay = runCli("view " + config("cave6") + " --frames 1 -q",
                                  "DISPLAY= WAYLAND_DISPLAY=");
  EXPECT_EQ(noDisplay.exitCode, 2) << noDisplay.output;
  EXPECT_NE(noDisplay.output.find("display"), std::string::npos) << noDisplay.output;

  REQUIRE_DISPLAY();
  nlohmann::json broken = nlohmann::json::parse(confvis::readTextFile(config("cave6")));
  broken["walls"][2]["window"] = {{"position", {5000, 5000}}, {"size", {100, 100}}};
  const fs::path file = scratch("view-off-screen.json");
  std::ofstream(file) << broken.dump();
  const CliRun run = runView(file.string() + " --frames 1 -o " + scratch("view-off").string());
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("wall 'right'"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("no monitor"), std::string::npos) << run.output;
}
