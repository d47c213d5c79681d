// A wall's optional "node": the cluster host or rank that draws it (runtime/cluster.hpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "confvis/base/error.hpp"
#include "confvis/engine/display_config.hpp"
#include "display_test_support.hpp"

using namespace confvis;
using confvis::testing::shippedConfigJson;
using nlohmann::json;

namespace {

json& wall(json& config, const std::string& name) {
  for (json& w : config["walls"])
    if (w["name"] == name) return w;
  throw std::logic_error("no wall " + name);
}

TEST(DisplayConfigNode, NamesAHostOrARankAndLeavesTheBakeHashAlone) {
  json config = shippedConfigJson("cave5.json");
  const DisplayConfig plain = parseDisplayConfig(config, "cave5.json");
  EXPECT_EQ(plain.wall("left").node, "");
  EXPECT_FALSE(toJson(plain)["walls"][0].contains("node"));

  wall(config, "left")["node"] = "render-2";
  wall(config, "right")["node"] = 3;
  const DisplayConfig placed = parseDisplayConfig(config, "cave5.json");
  EXPECT_EQ(placed.wall("left").node, "render-2");
  EXPECT_EQ(placed.wall("right").node, "3");
  // Which process draws a wall changes no map: the bake cache keeps its entry.
  EXPECT_EQ(placed.hash, plain.hash);
  const DisplayConfig again = parseDisplayConfig(toJson(placed), "round trip");
  EXPECT_EQ(again.wall("left").node, "render-2");
  EXPECT_EQ(again.wall("right").node, "3");
}

TEST(DisplayConfigNode, AnythingElseIsOneErrorNamingTheWall) {
  for (const json& bad : {json(-1), json(""), json(1.5), json::array({1}), json(true)}) {
    json config = shippedConfigJson("cave5.json");
    wall(config, "floor")["node"] = bad;
    try {
      (void)parseDisplayConfig(config, "broken.json");
      ADD_FAILURE() << "node " << bad.dump() << " accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("wall 'floor'"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("node"), std::string::npos) << e.what();
    }
  }
}

}  // namespace

namespace {

TEST(DisplayConfigNode, ImportersKeepTheHostThatDrawsEachWall) {
  const std::filesystem::path imported = std::filesystem::path(CONFVIS_SOURCE_DIR) / "configs/imported";
  // SGCT: each render node's address (one wall per node in this sample).
  for (const char* file : {"sgct-cave4.json", "sgct-cave4.xml"}) {
    const DisplayConfig sgct = loadDisplayConfig(imported / file);
    std::set<std::string> nodes;
    for (const Wall& wall : sgct.walls) {
      EXPECT_EQ(wall.node.rfind("10.0.0.1", 0), 0u) << file << ": " << wall.name << " " << wall.node;
      nodes.insert(wall.node);
    }
    EXPECT_EQ(nodes.size(), sgct.walls.size()) << file;
  }
  // ParaView: pvserver runs one process per <Machine> on the host it names.
  const DisplayConfig pvx = loadDisplayConfig(imported / "paraview-cave3.pvx");
  for (const Wall& wall : pvx.walls) EXPECT_EQ(wall.node, wall.name);
}

}  // namespace
