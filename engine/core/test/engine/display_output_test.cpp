// Per-wall live-display output (window placement, stereo layout): read, written back, kept out
// of the hash, carried over from SGCT and ParaView files, and every malformed entry one Error
// naming the wall.
#include <gtest/gtest.h>

#include <initializer_list>

#include "confvis/base/error.hpp"
#include "confvis/engine/display_config.hpp"
#include "confvis/engine/display_import.hpp"
#include "display_test_support.hpp"

using namespace confvis;
using confvis::testing::shippedConfigJson;
using nlohmann::json;

namespace {

json cave5WithFrontOutput(const json& output) {
  json config = shippedConfigJson("cave5.json");
  for (json& wall : config["walls"])
    if (wall["name"] == "front") wall.update(output);
  return config;
}

void expectInvalid(const json& output, std::initializer_list<std::string> fragments) {
  try {
    (void)parseDisplayConfig(cave5WithFrontOutput(output), "lab.json");
    ADD_FAILURE() << "expected an Error for " << output.dump();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput) << e.what();
    for (const std::string& fragment : fragments)
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos)
          << "message lacks \"" << fragment << "\": " << e.what();
  }
}

}  // namespace

TEST(DisplayOutput, WindowAndStereoOutputAreReadAndRoundTrip) {
  const json output = {{"window",
                        {{"position", {100, -20}}, {"size", {640, 480}}, {"decorated", false}}},
                       {"stereo_output", "side-by-side"}};
  const DisplayConfig config = parseDisplayConfig(cave5WithFrontOutput(output), "lab.json");
  const Wall& front = config.wall("front");
  ASSERT_TRUE(front.output.window);
  EXPECT_EQ(front.output.window->position, std::pair(100, -20));
  EXPECT_EQ(front.output.window->size, std::pair(640, 480));
  EXPECT_FALSE(front.output.window->decorated);
  EXPECT_FALSE(front.output.window->fullscreen);
  EXPECT_EQ(front.output.stereo, StereoOutput::SideBySide);
  EXPECT_TRUE(config.wall("left").output.empty());

  // toJson writes it back, so a config re-read (withReference, caches) keeps its windows.
  const DisplayConfig again = parseDisplayConfig(toJson(config), "again");
  EXPECT_EQ(again.wall("front").output.window->size, std::pair(640, 480));
  EXPECT_EQ(again.wall("front").output.stereo, StereoOutput::SideBySide);
  EXPECT_TRUE(again.wall("left").output.empty());
}

TEST(DisplayOutput, FullscreenTakesAMonitorIndexOrName) {
  const DisplayConfig byIndex = parseDisplayConfig(
      cave5WithFrontOutput({{"window", {{"fullscreen", 1}}}}), "lab.json");
  EXPECT_EQ(byIndex.wall("front").output.window->fullscreen->index, 1);
  EXPECT_TRUE(byIndex.wall("front").output.window->fullscreen->name.empty());
  const DisplayConfig byName = parseDisplayConfig(
      cave5WithFrontOutput({{"window", {{"fullscreen", "DP-2"}}}}), "lab.json");
  EXPECT_EQ(byName.wall("front").output.window->fullscreen->name, "DP-2");
  EXPECT_EQ(byName.wall("front").output.window->fullscreen->index, -1);
}

TEST(DisplayOutput, WhereThePixelsGoDoesNotChangeTheHash) {
  // The hash keys baked maps: moving a window must not invalidate one.
  const DisplayConfig plain = parseDisplayConfig(shippedConfigJson("cave5.json"), "cave5.json");
  const DisplayConfig placed = parseDisplayConfig(
      cave5WithFrontOutput({{"window", {{"position", {0, 0}}}}, {"stereo_output", "left"}}),
      "cave5.json");
  EXPECT_EQ(plain.hash, placed.hash);
  // ... while the geometry still does.
  json moved = shippedConfigJson("cave5.json");
  moved["walls"][0]["resolution"] = {1000, 1000};
  EXPECT_NE(parseDisplayConfig(moved, "cave5.json").hash, plain.hash);
}

TEST(DisplayOutput, MalformedOutputsNameTheWall) {
  expectInvalid({{"window", {{"size", {0, 480}}}}}, {"lab.json", "wall 'front' window", "'size'", "1 x 1"});
  expectInvalid({{"window", {{"size", {640}}}}}, {"wall 'front' window", "'size'", "2 integers"});
  expectInvalid({{"window", {{"position", {1.5, 0}}}}}, {"wall 'front' window", "'position'", "integers"});
  expectInvalid({{"window", {{"positon", {0, 0}}}}}, {"wall 'front' window", "unknown key 'positon'"});
  expectInvalid({{"window", {{"fullscreen", -1}}}}, {"wall 'front' window", "'fullscreen'"});
  expectInvalid({{"window", {{"fullscreen", ""}}}}, {"wall 'front' window", "'fullscreen'"});
  expectInvalid({{"window", {{"fullscreen", 0}, {"position", {0, 0}}}}},
                {"wall 'front' window", "not both"});
  expectInvalid({{"window", {{"decorated", "yes"}}}}, {"wall 'front' window", "'decorated'"});
  expectInvalid({{"window", {{"size", {100000, 480}}}}}, {"wall 'front' window", "out of range"});
  expectInvalid({{"window", "fullscreen"}}, {"wall 'front' window", "JSON object"});
  expectInvalid({{"stereo_output", "sbs"}}, {"wall 'front'", "'stereo_output'", "side-by-side", "\"sbs\""});
  expectInvalid({{"stereo_output", 1}}, {"wall 'front'", "'stereo_output'"});
}

TEST(DisplayOutput, SgctWindowsCarryTheirPlacementAndStereoMode) {
  const std::string text = R"({"version": 1, "nodes": [{"address": "localhost", "port": 20401,
    "windows": [
      {"name": "front", "pos": {"x": 10, "y": 20}, "size": {"x": 800, "y": 600}, "border": false,
       "stereo": "side_by_side", "viewports": [{"projection": {"type": "ProjectionPlane",
        "lowerleft": {"x": -1.5, "y": -1.5, "z": -1.5}, "upperleft": {"x": -1.5, "y": 1.5, "z": -1.5},
        "upperright": {"x": 1.5, "y": 1.5, "z": -1.5}}}]},
      {"name": "left", "fullscreen": true, "monitor": 1, "size": {"x": 1920, "y": 1920},
       "stereo": "active", "viewports": [{"eye": "right", "projection": {"type": "ProjectionPlane",
        "lowerleft": {"x": -1.5, "y": -1.5, "z": 1.5}, "upperleft": {"x": -1.5, "y": 1.5, "z": 1.5},
        "upperright": {"x": -1.5, "y": 1.5, "z": -1.5}}}]}]}],
    "users": [{"pos": {"x": 0, "y": 0, "z": 0}}]})";
  const DisplayConfig config = parseSgctJson(text, "lab.json");
  const WallOutput& front = config.wall("front").output;
  ASSERT_TRUE(front.window);
  EXPECT_EQ(front.window->position, std::pair(10, 20));
  EXPECT_EQ(front.window->size, std::pair(800, 600));
  EXPECT_FALSE(front.window->decorated);
  EXPECT_EQ(front.stereo, StereoOutput::SideBySide);
  const WallOutput& left = config.wall("left").output;
  ASSERT_TRUE(left.window && left.window->fullscreen);
  EXPECT_EQ(left.window->fullscreen->index, 1);
  EXPECT_EQ(left.stereo, StereoOutput::Right);  // the viewport's eye wins over active stereo
}

TEST(DisplayOutput, SgctXmlWindowsCarryTheirPlacement) {
  const std::string text = R"(<?xml version="1.0"?>
<Cluster masterAddress="localhost"><Node address="localhost" port="20401">
  <Window fullScreen="false" border="true"><Stereo type="top_bottom" />
    <Pos x="-100" y="50" /><Size x="1024" y="768" />
    <Viewport><Pos x="0" y="0" /><Size x="1.0" y="1.0" /><Viewplane>
      <Pos x="-1.5" y="-1.5" z="-1.5" /><Pos x="-1.5" y="1.5" z="-1.5" /><Pos x="1.5" y="1.5" z="-1.5" />
    </Viewplane></Viewport></Window></Node>
<User eyeSeparation="0.065"><Pos x="0" y="0" z="0" /></User></Cluster>)";
  const DisplayConfig config = parseSgctXml(text, "lab.xml");
  const WallOutput& wall = config.walls.at(0).output;
  ASSERT_TRUE(wall.window);
  EXPECT_EQ(wall.window->position, std::pair(-100, 50));
  EXPECT_EQ(wall.window->size, std::pair(1024, 768));
  EXPECT_TRUE(wall.window->decorated);
  EXPECT_EQ(wall.stereo, StereoOutput::TopBottom);
}

TEST(DisplayOutput, ParaViewGeometryPlacesTheWindow) {
  const std::string text = R"(<?xml version="1.0" ?><pvx><Process Type="server">
    <Machine Name="front" Geometry="960x540+1920+-10" LowerLeft="-1.5 -1.5 -1.5"
      LowerRight="1.5 -1.5 -1.5" UpperRight="1.5 1.5 -1.5"/></Process></pvx>)";
  const DisplayConfig config = parseParaViewPvx(text, "lab.pvx");
  const WallOutput& front = config.wall("front").output;
  ASSERT_TRUE(front.window);
  EXPECT_EQ(front.window->position, std::pair(1920, -10));
  EXPECT_EQ(front.window->size, std::pair(960, 540));
  EXPECT_FALSE(front.stereo);
  EXPECT_EQ(config.wall("front").width, 960);
}
