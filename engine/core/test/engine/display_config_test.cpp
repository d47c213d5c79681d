// Display configs: the shipped files, the wall geometry helpers, defaults, the canonical JSON
// and its hash. Invalid inputs are in display_config_errors_test.cpp.
#include "confvis/engine/display_config.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "confvis/base/error.hpp"
#include "display_test_support.hpp"

using namespace confvis;
using confvis::testing::configDir;
using confvis::testing::shippedConfig;
using confvis::testing::shippedConfigJson;
using confvis::testing::vecNear;
using nlohmann::json;

namespace {

std::vector<std::string> wallNames(const DisplayConfig& config) {
  std::vector<std::string> names;
  for (const Wall& w : config.walls) names.push_back(w.name);
  return names;
}

double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

}  // namespace

TEST(DisplayConfig, EveryShippedConfigLoadsWithTheDocumentedWalls) {
  using Names = std::vector<std::string>;
  const std::map<std::string, Names> expected{
      {"cave6.json", {"front", "left", "right", "back", "floor", "ceiling"}},
      {"cave5.json", {"front", "left", "right", "back", "floor"}},
      {"cave4.json", {"front", "left", "right", "floor"}},
      {"cave3.json", {"front", "left", "right"}},
      {"md230x6.json",
       {"top-left", "top-center", "top-right", "bottom-left", "bottom-center", "bottom-right"}},
      {"flat-wall.json", {"screen"}}};
  std::set<std::string> found;
  for (const auto& entry : std::filesystem::directory_iterator(configDir())) {
    if (entry.path().extension() != ".json") continue;
    const std::string file = entry.path().filename().string();
    found.insert(file);
    SCOPED_TRACE(file);
    const DisplayConfig config = loadDisplayConfig(entry.path());
    ASSERT_TRUE(expected.count(file)) << "shipped config without a test expectation";
    EXPECT_EQ(wallNames(config), expected.at(file));
    EXPECT_EQ(config.name + ".json", file);
    EXPECT_EQ(config.hash.size(), 16u);
    for (const Wall& w : config.walls)  // every wall faces the reference, at a real distance
      EXPECT_GT(glm::dot(w.normal(), config.reference - w.lowerLeft), 0.1) << w.name;
  }
  EXPECT_EQ(found.size(), expected.size());
}

TEST(DisplayConfig, CaveWallsFollowTheVerticalCrossConvention) {
  const DisplayConfig cave = shippedConfig("cave6.json");
  EXPECT_TRUE(vecNear(cave.reference, {0, 0, 0}));
  EXPECT_EQ(cave.source, SourceField::FullSphere);
  const std::map<std::string, glm::dvec3> inwardNormals{
      {"front", {0, 0, 1}}, {"back", {0, 0, -1}}, {"left", {1, 0, 0}},
      {"right", {-1, 0, 0}}, {"floor", {0, 1, 0}}, {"ceiling", {0, -1, 0}}};
  for (const auto& [name, normal] : inwardNormals) {
    const Wall& w = cave.wall(name);
    EXPECT_TRUE(vecNear(w.normal(), normal)) << name;
    EXPECT_DOUBLE_EQ(w.widthMetres(), 3.0) << name;
    EXPECT_DOUBLE_EQ(w.heightMetres(), 3.0) << name;
    EXPECT_EQ(w.width, 1920);
    EXPECT_EQ(w.height, 1920);
  }
  const Wall& front = cave.wall("front");
  // Ceiling above the front wall, floor below it, as in the preview cross.
  EXPECT_TRUE(vecNear(cave.wall("ceiling").lowerLeft, front.upperLeft));
  EXPECT_TRUE(vecNear(cave.wall("ceiling").lowerRight, front.upperRight()));
  EXPECT_TRUE(vecNear(cave.wall("floor").upperLeft, front.lowerLeft));
  EXPECT_TRUE(vecNear(cave.wall("floor").upperRight(), front.lowerRight));
  // Left and right walls continue the front wall sideways.
  EXPECT_TRUE(vecNear(cave.wall("left").lowerRight, front.lowerLeft));
  EXPECT_TRUE(vecNear(cave.wall("right").lowerLeft, front.lowerRight));
}

TEST(DisplayConfig, Md230x6ModelsTheAngledThreeByTwoMonitorArray) {
  const DisplayConfig md = shippedConfig("md230x6.json");
  EXPECT_EQ(md.source, SourceField::Hemisphere);
  EXPECT_TRUE(vecNear(md.hemisphereAxis, {0, 0, -1}));
  for (const Wall& w : md.walls) {
    EXPECT_EQ(w.width, 1920);
    EXPECT_EQ(w.height, 1080);
    const Wall lit = w.litRectangle();
    EXPECT_NEAR(lit.widthMetres(), 0.509, 1e-3) << w.name;
    EXPECT_NEAR(lit.heightMetres(), 0.286, 1e-3) << w.name;
    EXPECT_NEAR(w.bezel.left + w.bezel.right, 0.0055, 1e-9) << w.name;  // one seam per joint
  }
  const Wall& centre = md.wall("top-center");
  EXPECT_NEAR(glm::dot(centre.normal(), md.reference - centre.lowerLeft), 0.65, 1e-9);
  for (const char* outer : {"top-left", "top-right", "bottom-left", "bottom-right"}) {
    const double angle = degrees(std::acos(glm::dot(md.wall(outer).normal(), centre.normal())));
    EXPECT_GT(angle, 30.0) << outer;
    EXPECT_LT(angle, 40.0) << outer;
  }
  // Columns share vertical edges, rows share horizontal ones.
  EXPECT_TRUE(vecNear(md.wall("top-left").lowerRight, centre.lowerLeft));
  EXPECT_TRUE(vecNear(md.wall("top-right").lowerLeft, centre.lowerRight));
  EXPECT_TRUE(vecNear(md.wall("bottom-center").upperLeft, centre.lowerLeft));
  const double unfoldedWidth = 3 * centre.widthMetres(), height = 2 * centre.heightMetres();
  EXPECT_NEAR(unfoldedWidth / height, 2.66, 0.03);
}

TEST(DisplayConfig, FlatWallIsASixteenByNineScreenInFront) {
  const DisplayConfig flat = shippedConfig("flat-wall.json");
  ASSERT_EQ(flat.walls.size(), 1u);
  const Wall& w = flat.walls[0];
  EXPECT_DOUBLE_EQ(w.widthMetres(), 3.0);
  EXPECT_DOUBLE_EQ(w.heightMetres(), 1.6875);
  EXPECT_EQ(w.width, 3840);
  EXPECT_EQ(w.height, 2160);
  EXPECT_TRUE(vecNear(w.pointAt(0.5, 0.5), {0, 0, -1.5}));
  EXPECT_EQ(flat.source, SourceField::Hemisphere);
}

TEST(DisplayWall, HelpersDescribeTheRectangle) {
  Wall w{"w", {1, 0, 0}, {1, 0, -4}, {1, 2, 0}, 400, 200, {}, {}, {}};  // like a CAVE's left wall
  EXPECT_TRUE(vecNear(w.upperRight(), {1, 2, -4}));
  EXPECT_TRUE(vecNear(w.right(), {0, 0, -1}));
  EXPECT_TRUE(vecNear(w.up(), {0, 1, 0}));
  EXPECT_TRUE(vecNear(w.normal(), {1, 0, 0}));  // right x up, toward +x
  EXPECT_DOUBLE_EQ(w.widthMetres(), 4.0);
  EXPECT_DOUBLE_EQ(w.heightMetres(), 2.0);
  EXPECT_TRUE(vecNear(w.pointAt(0.25, 0.5), {1, 1, -1}));
  // corners() runs counter-clockwise seen from the front: each turn points along the normal.
  const std::array<glm::dvec3, 4> c = w.corners();
  EXPECT_TRUE(vecNear(c[0], w.lowerLeft) && vecNear(c[2], w.upperRight()));
  for (int k = 0; k < 4; ++k) {
    const glm::dvec3 turn = glm::cross(c[(k + 1) % 4] - c[k], c[(k + 2) % 4] - c[(k + 1) % 4]);
    EXPECT_GT(glm::dot(turn, w.normal()), 0.0) << "corner " << k;
  }
}

TEST(DisplayWall, PixelCentresCountRowsFromTheTop) {
  Wall w{"w", {0, 0, 0}, {4, 0, 0}, {0, 2, 0}, 4, 2, {}, {}, {}};  // 1 m pixels
  EXPECT_TRUE(vecNear(w.pixelCenter(0, 0), {0.5, 1.5, 0}));
  EXPECT_TRUE(vecNear(w.pixelCenter(3, 1), {3.5, 0.5, 0}));
  EXPECT_TRUE(vecNear(w.pixelCenter(1, 1), {1.5, 0.5, 0}));
}

TEST(DisplayWall, LitRectangleIsTheWallMinusItsBezels) {
  Wall w{"w", {0, 0, 0}, {4, 0, 0}, {0, 2, 0}, 8, 4, {0.1, 0.2, 0.3, 0.4}, {}, {}};
  const Wall lit = w.litRectangle();
  EXPECT_TRUE(vecNear(lit.lowerLeft, {0.1, 0.3, 0}));
  EXPECT_TRUE(vecNear(lit.lowerRight, {3.8, 0.3, 0}));
  EXPECT_TRUE(vecNear(lit.upperLeft, {0.1, 1.6, 0}));
  EXPECT_TRUE(vecNear(lit.upperRight(), {3.8, 1.6, 0}));
  EXPECT_EQ(lit.name, "w");
  EXPECT_EQ(lit.width, 8);
  EXPECT_EQ(lit.bezel.left + lit.bezel.right + lit.bezel.bottom + lit.bezel.top, 0.0);
}

TEST(DisplayConfig, OptionalFieldsTakeTheDocumentedDefaults) {
  const json minimal = {
      {"name", "minimal"},
      {"walls",
       {{{"name", "front"},
         {"lower_left", {-1, -1, -1}},
         {"lower_right", {1, -1, -1}},
         {"upper_left", {-1, 1, -1}},
         {"resolution", {640, 640}}}}}};
  const DisplayConfig c = parseDisplayConfig(minimal, "minimal");
  EXPECT_TRUE(vecNear(c.reference, {0, 0, 0}));
  EXPECT_EQ(c.source, SourceField::FullSphere);
  EXPECT_TRUE(vecNear(c.hemisphereAxis, {0, 0, -1}));
  // Without edge_length: 20 cm scaled by the wall's distance (1 m) over a CAVE's 1.5 m
  // (default_edge_length.hpp).
  EXPECT_DOUBLE_EQ(c.edgeLength, 0.20 / 1.5);
  EXPECT_EQ(c.cubeResolution, 256);
  EXPECT_DOUBLE_EQ(c.eyeSeparation, 0.064);
  EXPECT_EQ(c.walls[0].bezel.left, 0.0);
}

TEST(DisplayConfig, HemisphereAxisIsNormalised) {
  json j = shippedConfigJson("flat-wall.json");
  j["source"]["axis"] = {0, 0, -5};
  EXPECT_TRUE(vecNear(parseDisplayConfig(j, "t").hemisphereAxis, {0, 0, -1}));
}

TEST(DisplayConfig, CanonicalJsonRoundTripsAndKeepsTheHash) {
  for (const char* file : {"cave5.json", "md230x6.json"}) {
    const DisplayConfig c = shippedConfig(file);
    const DisplayConfig again = parseDisplayConfig(toJson(c), "round trip");
    EXPECT_EQ(toJson(again), toJson(c)) << file;
    EXPECT_EQ(again.hash, c.hash) << file;
  }
}

TEST(DisplayConfig, HashIdentifiesTheDisplayNotTheFileLayout) {
  const json original = shippedConfigJson("cave4.json");
  const std::string hash = parseDisplayConfig(original, "a").hash;
  // Same content written differently (defaults spelled out or left out): same hash.
  json spelledOut = original;
  spelledOut["walls"][0]["bezel"] = {{"left", 0.0}};
  spelledOut.erase("stereo");
  EXPECT_EQ(parseDisplayConfig(spelledOut, "b").hash, hash);
  // Different geometry or settings: different hash.
  json moved = original;
  moved["walls"][0]["resolution"] = {1920, 1919};
  EXPECT_NE(parseDisplayConfig(moved, "c").hash, hash);
  json finer = original;
  finer["edge_length"] = 0.05;
  EXPECT_NE(parseDisplayConfig(finer, "d").hash, hash);
}

TEST(DisplayConfig, WallLookupNamesTheUnknownWallAndListsTheKnownOnes) {
  const DisplayConfig cave = shippedConfig("cave3.json");
  EXPECT_EQ(&cave.wall("left"), &cave.walls[1]);
  try {
    cave.wall("ceiling");
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput);
    const std::string message = e.what();
    EXPECT_NE(message.find("'ceiling'"), std::string::npos) << message;
    EXPECT_NE(message.find("'front', 'left', 'right'"), std::string::npos) << message;
  }
}
