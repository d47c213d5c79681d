// Window layout of a live display without a window system: eyes per stereo_output, content
// sizes, tiling over the work area, fullscreen monitors by index and name, and placement errors
// naming the wall. Plus the frame log's percentiles and the window's sRGB codes.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "confvis/base/error.hpp"
#include "confvis/base/png_io.hpp"
#include "confvis/runtime/frame_log.hpp"
#include "confvis/runtime/window_content.hpp"
#include "confvis/runtime/window_plan.hpp"

using namespace confvis;
using nlohmann::json;

namespace {

// Two 1000 x 500 walls of a flat 2 m x 1 m pair facing the reference.
json twoWalls() {
  return {{"name", "pair"},
          {"walls",
           {{{"name", "a"}, {"lower_left", {-2, -0.5, -1}}, {"lower_right", {0, -0.5, -1}},
             {"upper_left", {-2, 0.5, -1}}, {"resolution", {1000, 500}}},
            {{"name", "b"}, {"lower_left", {0, -0.5, -1}}, {"lower_right", {2, -0.5, -1}},
             {"upper_left", {0, 0.5, -1}}, {"resolution", {1000, 500}}}}}};
}

const std::vector<MonitorInfo> kMonitors = {
    {"DP-1", 0, 0, 1920, 1080, 0, 30, 1920, 1050},
    {"HDMI-2", 1920, 0, 1280, 1024, 1920, 0, 1280, 1024}};

}  // namespace

TEST(WindowPlan, MonoRunTilesOneWindowPerWallOverTheWorkArea) {
  const DisplayConfig config = parseDisplayConfig(twoWalls(), "pair.json");
  const std::vector<WindowPlan> plans = planWindows(config, false, 0.5, kMonitors);
  ASSERT_EQ(plans.size(), 2u);
  EXPECT_EQ(plans[0].eyes, std::vector<Eye>{Eye::Center});
  EXPECT_EQ(plans[0].contentWidth, 500);
  EXPECT_EQ(plans[0].contentHeight, 250);
  EXPECT_EQ(plans[0].x, 0);
  EXPECT_EQ(plans[0].y, 30);  // below the panel
  EXPECT_EQ(plans[1].x, 500);
  EXPECT_EQ(plans[1].width, 500);
}

TEST(WindowPlan, TooLargeWindowsShrinkTogetherUntilTheyFit) {
  const DisplayConfig config = parseDisplayConfig(twoWalls(), "pair.json");
  const std::vector<WindowPlan> plans = planWindows(config, true, 1.0, kMonitors);
  // Side by side: 2000 x 500 content per wall, two rows of it do not fit 1920 x 1050.
  EXPECT_EQ(plans[0].contentWidth, 2000);
  for (const WindowPlan& plan : plans) {
    EXPECT_LE(plan.x + plan.width, 1920);
    EXPECT_LE(plan.y + plan.height, 1080);
    EXPECT_NEAR(double(plan.width) / plan.height, 4.0, 0.05);
  }
}

TEST(WindowPlan, StereoOutputsLayTheEyesOut) {
  json config = twoWalls();
  config["walls"][0]["stereo_output"] = "top-bottom";
  config["walls"][1]["stereo_output"] = "right";
  const DisplayConfig display = parseDisplayConfig(config, "pair.json");
  const std::vector<WindowPlan> stereo = planWindows(display, true, 0.1, kMonitors);
  ASSERT_EQ(stereo[0].regions.size(), 2u);
  EXPECT_EQ(stereo[0].regions[1].eye, Eye::Right);
  EXPECT_EQ(stereo[0].regions[1].y, 50);
  EXPECT_EQ(stereo[0].contentHeight, 100);
  EXPECT_EQ(stereo[0].eyes, (std::vector<Eye>{Eye::Left, Eye::Right}));
  EXPECT_EQ(stereo[1].eyes, std::vector<Eye>{Eye::Right});
  // A mono run shows the centre eye wherever a layout has an eye.
  const std::vector<WindowPlan> mono = planWindows(display, false, 0.1, kMonitors);
  EXPECT_EQ(mono[0].eyes, std::vector<Eye>{Eye::Center});
  EXPECT_EQ(mono[0].regions.size(), 2u);
  EXPECT_EQ(mono[1].eyes, std::vector<Eye>{Eye::Center});
}

TEST(WindowPlan, PlacedAndFullscreenWindows) {
  json config = twoWalls();
  config["walls"][0]["window"] = {{"position", {2000, 100}}, {"size", {640, 320}},
                                  {"decorated", false}};
  config["walls"][1]["window"] = {{"fullscreen", "HDMI"}};
  const std::vector<WindowPlan> plans =
      planWindows(parseDisplayConfig(config, "pair.json"), false, 1.0, kMonitors);
  EXPECT_EQ(plans[0].x, 2000);
  EXPECT_EQ(plans[0].width, 640);
  EXPECT_FALSE(plans[0].decorated);
  EXPECT_EQ(plans[0].contentWidth, 1000);  // stretched into the window
  EXPECT_EQ(plans[1].fullscreenMonitor, 1);
  EXPECT_EQ(plans[1].width, 1280);
}

TEST(WindowPlan, WindowsOffEveryMonitorNameTheWall) {
  json config = twoWalls();
  config["walls"][1]["window"] = {{"position", {3200, 0}}, {"size", {100, 100}}};
  try {
    (void)planWindows(parseDisplayConfig(config, "pair.json"), false, 1.0, kMonitors);
    ADD_FAILURE() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("wall 'b'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no monitor"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("HDMI-2"), std::string::npos) << e.what();
  }
  config["walls"][1]["window"] = {{"fullscreen", 2}};
  try {
    (void)planWindows(parseDisplayConfig(config, "pair.json"), false, 1.0, kMonitors);
    ADD_FAILURE() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("wall 'b'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("monitor 2"), std::string::npos) << e.what();
  }
}

TEST(WindowContent, CodesAreThePngPreviewsAndEyesLandInTheirRegions) {
  // writePng's code: lround(255 * linearToSrgb(v)); the table must agree for every code.
  for (int k = 0; k < 256; ++k) {
    const float linear = srgbToLinear(k / 255.0f);
    EXPECT_EQ(srgbCode(linear), k) << linear;
  }
  EXPECT_EQ(srgbCode(-1.0f), 0);
  EXPECT_EQ(srgbCode(7.0f), 255);
  EXPECT_EQ(srgbCode(std::nanf("")), 0);

  WindowPlan plan;
  plan.wall = "w";
  plan.regions = {{Eye::Left, 0, 0, 2, 1}, {Eye::Right, 2, 0, 2, 1}};
  plan.contentWidth = 4;
  plan.contentHeight = 1;
  const ImageRGBA left(2, 1, 0.0f), right(2, 1, 1.0f);
  std::vector<std::uint8_t> out(16, 7);
  composeWindow(plan, [&](Eye eye) { return eye == Eye::Left ? &left : &right; }, out.data());
  EXPECT_EQ(out, (std::vector<std::uint8_t>{0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255, 255,
                                            255, 255, 255, 255}));
  const ImageRGBA wrongSize(3, 1, 0.0f);
  EXPECT_THROW(composeWindow(plan, [&](Eye) { return &wrongSize; }, out.data()), Error);
}

TEST(FrameLog, NearestRankPercentilesAndTheBakingSplit) {
  std::vector<double> times;
  for (int i = 1; i <= 200; ++i) times.push_back(i * 1e-3);
  const FrameTimeSummary s = summarize(times);
  EXPECT_EQ(s.frames, 200);
  EXPECT_DOUBLE_EQ(s.meanSeconds, 100.5e-3);
  EXPECT_DOUBLE_EQ(s.p50Seconds, 100e-3);
  EXPECT_DOUBLE_EQ(s.p99Seconds, 198e-3);
  EXPECT_DOUBLE_EQ(s.maxSeconds, 200e-3);
  EXPECT_EQ(summarize({}).frames, 0);

  FrameLog log;
  log.add({.frameSeconds = 0.010, .bakeInFlight = false});
  log.add({.frameSeconds = 0.030, .bakeInFlight = true});
  log.add({.frameSeconds = 0.012, .bakeInFlight = false});
  EXPECT_EQ(log.summary(true).frames, 1);
  EXPECT_DOUBLE_EQ(log.summary(true).maxSeconds, 0.030);
  EXPECT_DOUBLE_EQ(log.summary(false).p99Seconds, 0.012);
  const nlohmann::json report = log.toJson();
  EXPECT_EQ(report["frames"].size(), 3u);
  EXPECT_EQ(report["frames"][1]["bake_in_flight"], true);
  EXPECT_DOUBLE_EQ(report["frame_time_baking"]["max_ms"].get<double>(), 30.0);
}
