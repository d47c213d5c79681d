// Projection walls: projectors overlapping on one plane form one display surface, a window
// covering them is a preview, the edge-blend ramps sum to one in linear light, and the shipped
// SGCT projector samples (configs/imported/sgct-projectors*) import as such.
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>

#include "confvis/base/error.hpp"
#include "confvis/engine/display_import.hpp"
#include "confvis/engine/display_surfaces.hpp"
#include "display_test_support.hpp"

using namespace confvis;
using confvis::testing::configDir;
using confvis::testing::vecNear;
using nlohmann::json;

namespace {

// A flat screen at z = -2 facing the origin, x in [x0, x1], y in [0.6, 1.95].
json screenWall(const std::string& name, double x0, double x1, int width = 1920) {
  return {{"name", name},
          {"lower_left", {x0, 0.6, -2.0}},
          {"lower_right", {x1, 0.6, -2.0}},
          {"upper_left", {x0, 1.95, -2.0}},
          {"resolution", {width, 1080}}};
}

// Two 2.4 m projectors overlapping by 0.4 m (x in [-0.2, 0.2]), as sgct-projectors2.xml.
json twoProjectors() {
  return {{"name", "projectors"},
          {"reference", {0.0, 1.2, 0.0}},
          {"source", {{"field", "hemisphere"}}},
          {"walls", {screenWall("left", -2.2, 0.2), screenWall("right", -0.2, 2.2)}}};
}

void expectInvalid(const json& config, std::initializer_list<std::string> fragments) {
  try {
    (void)parseDisplayConfig(config, "wall.json");
    FAIL() << "accepted: " << config.dump();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput);
    for (const std::string& f : fragments)
      EXPECT_NE(std::string(e.what()).find(f), std::string::npos) << e.what() << " lacks " << f;
  }
}

std::filesystem::path imported(const std::string& file) { return configDir() / "imported" / file; }

bool anyNoteHas(const ImportReport& report, std::initializer_list<std::string> fragments) {
  for (const std::string& note : report.notes) {
    bool all = true;
    for (const std::string& f : fragments) all = all && note.find(f) != std::string::npos;
    if (all) return true;
  }
  return false;
}

TEST(DisplaySurfaces, OverlappingProjectorsFormOneSurfaceTheirUnion) {
  const DisplayConfig config = parseDisplayConfig(twoProjectors(), "wall.json");
  const std::vector<DisplaySurface> surfaces = displaySurfaces(config);
  ASSERT_EQ(surfaces.size(), 1u);
  EXPECT_EQ(surfaces[0].walls, (std::vector<int>{0, 1}));
  EXPECT_EQ(surfaces[0].rectangle.name, "left+right");
  EXPECT_TRUE(vecNear(surfaces[0].rectangle.lowerLeft, {-2.2, 0.6, -2.0}, 1e-12));
  EXPECT_TRUE(vecNear(surfaces[0].rectangle.lowerRight, {2.2, 0.6, -2.0}, 1e-12));
  EXPECT_TRUE(vecNear(surfaces[0].rectangle.upperLeft, {-2.2, 1.95, -2.0}, 1e-12));
  const DisplayConfig forMap = surfaceConfig(config);
  ASSERT_EQ(forMap.walls.size(), 1u);
  EXPECT_NEAR(forMap.walls[0].widthMetres(), 4.4, 1e-12);
  // Walls that only touch stay separate surfaces, and the config is left as it is.
  json touching = twoProjectors();
  touching["walls"] = {screenWall("left", -2.2, 0.0), screenWall("right", 0.0, 2.2)};
  const DisplayConfig tiled = parseDisplayConfig(touching, "tiled.json");
  EXPECT_EQ(displaySurfaces(tiled).size(), 2u);
  EXPECT_EQ(surfaceConfig(tiled).walls.size(), 2u);
}

TEST(DisplaySurfaces, APreviewIsNoSurfaceAndMustLieInsideOne) {
  json j = twoProjectors();
  json preview = screenWall("preview", -2.2, 2.2, 1280);
  preview["preview"] = true;
  j["walls"].push_back(preview);
  const DisplayConfig config = parseDisplayConfig(j, "wall.json");
  EXPECT_TRUE(config.walls[2].preview);
  const std::vector<DisplaySurface> surfaces = displaySurfaces(config);
  ASSERT_EQ(surfaces.size(), 1u);
  EXPECT_EQ(surfaces[0].walls, (std::vector<int>{0, 1}));
  EXPECT_EQ(surfaceConfig(config).walls.size(), 1u);
  EXPECT_EQ(toJson(config)["walls"][2]["preview"], true);
  EXPECT_FALSE(toJson(config)["walls"][0].contains("preview"));

  // Unmarked, the covering window is refused with the fix.
  json unmarked = j;
  unmarked["walls"][2].erase("preview");
  expectInvalid(unmarked, {"wall.json", "'preview'", "covers", "\"preview\": true"});
  // A preview reaching past the projectors shows no display.
  json outside = j;
  outside["walls"][2]["lower_right"][0] = 2.5;
  expectInvalid(outside, {"preview wall 'preview'", "inside no display surface"});
  json wrongType = j;
  wrongType["walls"][2]["preview"] = "yes";
  expectInvalid(wrongType, {"wall 'preview'", "'preview' must be true or false"});
}

TEST(DisplaySurfaces, OverlapsThatFormNoSurfaceAreNamed) {
  json rotated = twoProjectors();  // the right projector upside down: sides antiparallel
  rotated["walls"][1] = {{"name", "right"},
                         {"lower_left", {2.2, 1.95, -2.0}},
                         {"lower_right", {-0.2, 1.95, -2.0}},
                         {"upper_left", {2.2, 0.6, -2.0}},
                         {"resolution", {1920, 1080}}};
  expectInvalid(rotated, {"wall.json", "'left' and 'right' overlap", "parallel sides"});
  json bezel = twoProjectors();
  bezel["walls"][0]["bezel"] = {{"left", 0.01}};
  expectInvalid(bezel, {"'left' and 'right' overlap", "bezel"});
  json notch = twoProjectors();  // a third projector below the left one only: an L shape
  json lower = screenWall("lower", -2.2, 0.2);
  for (const char* corner : {"lower_left", "lower_right"}) lower[corner][1] = -0.6;
  lower["upper_left"][1] = 0.7;
  notch["walls"].push_back(lower);
  expectInvalid(notch, {"'left', 'right', 'lower'", "do not fill a rectangle"});
}

// The closed form: across the overlap x in [-0.2, 0.2] the left projector's light falls
// linearly from 1 to 0, the right one's rises; the signal masks are weight^(1/gamma).
TEST(DisplaySurfaces, BlendRampsSumToOneInLinearLight) {
  json j = twoProjectors();
  j["edge_blend"] = {{"gamma", 2.2}};
  const DisplayConfig config = parseDisplayConfig(j, "wall.json");
  ASSERT_TRUE(config.edgeBlend.enabled);
  EXPECT_EQ(config.hash, parseDisplayConfig(twoProjectors(), "wall.json").hash);  // no map change
  const std::vector<DisplaySurface> surfaces = displaySurfaces(config);
  for (double x : {-0.19, -0.1, 0.0, 0.05, 0.17}) {
    const glm::dvec3 p(x, 1.3, -2.0);
    const double left = edgeBlendWeight(config, surfaces, 0, p);
    const double right = edgeBlendWeight(config, surfaces, 1, p);
    EXPECT_NEAR(left, (0.2 - x) / 0.4, 1e-12) << x;
    EXPECT_NEAR(right, (x + 0.2) / 0.4, 1e-12) << x;
    const double mLeft = std::pow(left, 1 / 2.2), mRight = std::pow(right, 1 / 2.2);
    EXPECT_NEAR(std::pow(mLeft, 2.2) + std::pow(mRight, 2.2), 1.0, 1e-12);
    EXPECT_GT(mLeft + mRight, 1.0 + 1e-3) << "signals themselves must not sum to one";
  }
  // Outside the overlap each projector alone, full; outside its own area nothing; the outer
  // edges (on the screen's outline) never fade.
  EXPECT_DOUBLE_EQ(edgeBlendWeight(config, surfaces, 0, {-1.0, 1.3, -2.0}), 1.0);
  EXPECT_DOUBLE_EQ(edgeBlendWeight(config, surfaces, 0, {-2.19, 0.61, -2.0}), 1.0);
  EXPECT_DOUBLE_EQ(edgeBlendWeight(config, surfaces, 0, {1.0, 1.3, -2.0}), 0.0);
  EXPECT_DOUBLE_EQ(edgeBlendWeight(config, surfaces, 1, {1.0, 1.3, -2.0}), 1.0);

  // The per-pixel mask of the left projector (1920 px over 2.4 m): the closed form at every
  // pixel centre of a row, and empty without blending.
  const std::vector<float> mask = edgeBlendSignal(config, 0, 1920, 1080);
  ASSERT_EQ(mask.size(), 1920u * 1080u);
  int ramped = 0;
  for (int x = 0; x < 1920; ++x) {
    const double px = -2.2 + (x + 0.5) * 2.4 / 1920;
    const double w = px <= -0.2 ? 1.0 : (0.2 - px) / 0.4;
    EXPECT_NEAR(mask[540u * 1920u + x], std::pow(w, 1 / 2.2), 1e-6) << x;
    ramped += w < 1.0;
  }
  EXPECT_EQ(ramped, 320);  // 0.4 m of 2.4 m
  json off = twoProjectors();
  EXPECT_TRUE(edgeBlendSignal(parseDisplayConfig(off, "wall.json"), 0, 1920, 1080).empty());
  json badGamma = j;
  badGamma["edge_blend"]["gamma"] = 0.0;
  expectInvalid(badGamma, {"edge_blend", "'gamma'"});
}

// Three projectors in a row: at every point the weights of those covering it sum to one.
TEST(DisplaySurfaces, ThreeProjectorSampleImportsAsOneSurfaceWithAPreview) {
  ImportOptions options;
  options.edgeBlendGamma = 1.8;
  ImportReport report;
  const DisplayConfig config = importDisplayConfig(imported("sgct-projectors3.json"), options, &report);
  ASSERT_EQ(config.walls.size(), 4u);
  EXPECT_EQ(config.walls[0].name, "master-preview");
  EXPECT_TRUE(config.walls[0].preview);
  EXPECT_EQ(config.walls[1].node, "10.1.0.11");
  EXPECT_TRUE(anyNoteHas(report, {"'master-preview'", "covers walls 'proj-1', 'proj-2', 'proj-3'",
                                  "preview", "--skip-window master-preview"}));
  const std::vector<DisplaySurface> surfaces = displaySurfaces(config);
  ASSERT_EQ(surfaces.size(), 1u);
  EXPECT_EQ(surfaces[0].walls, (std::vector<int>{1, 2, 3}));
  EXPECT_NEAR(surfaces[0].rectangle.widthMetres(), 6.6, 1e-9);
  EXPECT_TRUE(config.edgeBlend.enabled);
  EXPECT_DOUBLE_EQ(config.edgeBlend.gamma, 1.8);
  for (double x = -3.29; x < 3.3; x += 0.05) {
    const glm::dvec3 p(x, 1.0, -2.5);
    double sum = 0;
    for (int w = 1; w <= 3; ++w) sum += edgeBlendWeight(config, surfaces, w, p);
    EXPECT_NEAR(sum, 1.0, 1e-12) << x;
  }
  EXPECT_DOUBLE_EQ(edgeBlendWeight(config, surfaces, 0, {0.0, 1.0, -2.5}), 1.0);  // preview
  // Skipping the preview by hand leaves the projectors.
  options.skipWindows = {"master-preview"};
  const DisplayConfig skipped = importDisplayConfig(imported("sgct-projectors3.json"), options, &report);
  ASSERT_EQ(skipped.walls.size(), 3u);
  EXPECT_EQ(skipped.walls[0].name, "proj-1");
  EXPECT_TRUE(anyNoteHas(report, {"master-preview", "skipped"}));
  options.skipWindows = {"nosuch"};
  try {
    (void)importDisplayConfig(imported("sgct-projectors3.json"), options);
    FAIL() << "unknown window accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'nosuch' is not in the file"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("'proj-2'"), std::string::npos) << e.what();
  }
}

TEST(DisplaySurfaces, XmlSampleAndItsMillimetreTwinImportAlike) {
  ImportReport metresReport, mmReport;
  const DisplayConfig metres = importDisplayConfig(imported("sgct-projectors2.xml"), {}, &metresReport);
  const DisplayConfig mm = importDisplayConfig(imported("sgct-projectors2-mm.xml"), {}, &mmReport);
  ASSERT_EQ(metres.walls.size(), 3u);
  EXPECT_TRUE(metres.walls[0].preview);
  EXPECT_EQ(displaySurfaces(metres).size(), 1u);
  EXPECT_FALSE(anyNoteHas(metresReport, {"millimetres"}));
  EXPECT_TRUE(anyNoteHas(mmReport, {"sgct-projectors2-mm.xml", "millimetres", "--scale"}));
  ASSERT_EQ(mm.walls.size(), metres.walls.size());
  for (std::size_t i = 0; i < mm.walls.size(); ++i) {
    EXPECT_EQ(mm.walls[i].name, metres.walls[i].name);
    EXPECT_EQ(mm.walls[i].preview, metres.walls[i].preview);
    EXPECT_TRUE(vecNear(mm.walls[i].lowerLeft, metres.walls[i].lowerLeft, 1e-12));
    EXPECT_TRUE(vecNear(mm.walls[i].lowerRight, metres.walls[i].lowerRight, 1e-12));
    EXPECT_TRUE(vecNear(mm.walls[i].upperLeft, metres.walls[i].upperLeft, 1e-12));
  }
  EXPECT_TRUE(vecNear(mm.reference, {0.0, 1.2, 0.0}, 1e-12));
  EXPECT_NEAR(mm.eyeSeparation, 0.064, 1e-12);
  // An explicit unit wins over the guess.
  ImportOptions metresPerUnit;
  metresPerUnit.scale = 0.001;
  ImportReport explicitReport;
  const DisplayConfig given = importDisplayConfig(imported("sgct-projectors2-mm.xml"), metresPerUnit,
                                                  &explicitReport);
  EXPECT_FALSE(anyNoteHas(explicitReport, {"millimetres"}));
  EXPECT_TRUE(vecNear(given.walls[1].lowerLeft, metres.walls[1].lowerLeft, 1e-12));
}

TEST(DisplaySurfaces, ADisplayTooLargeForMillimetresAsksForTheScale) {
  const std::string huge = R"(<Cluster><Node><Window><Size x="100" y="100"/><Viewport><Viewplane>
      <Pos x="-2e5" y="-1e5" z="-3e5"/><Pos x="-2e5" y="1e5" z="-3e5"/><Pos x="2e5" y="1e5" z="-3e5"/>
      </Viewplane></Viewport></Window></Node></Cluster>)";
  try {
    (void)parseSgctXml(huge, "km.xml");
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("km.xml"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--scale"), std::string::npos) << e.what();
  }
  ImportOptions metresPerUnit;
  metresPerUnit.scale = 1e-5;  // given by hand, it imports
  EXPECT_NEAR(parseSgctXml(huge, "km.xml", metresPerUnit).walls[0].widthMetres(), 4.0, 1e-9);
}

}  // namespace
