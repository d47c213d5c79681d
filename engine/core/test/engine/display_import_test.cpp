// SGCT and ParaView display descriptions import to exactly the walls of the confvis configs they
// mirror (configs/imported/README.md), and malformed files give one Error naming file and element.
#include <gtest/gtest.h>

#include <fstream>
#include <initializer_list>
#include <unistd.h>

#include "confvis/base/error.hpp"
#include "confvis/engine/display_import.hpp"
#include "display_test_support.hpp"

using namespace confvis;
using confvis::testing::configDir;
using confvis::testing::shippedConfig;
using confvis::testing::shippedConfigJson;
using confvis::testing::vecNear;
namespace fs = std::filesystem;

namespace {

fs::path imported(const std::string& file) { return configDir() / "imported" / file; }

// A shipped confvis config moved by `offset`, renamed: what an import of the same display in
// another frame must reproduce, hash included (the hash covers every field).
DisplayConfig shippedMoved(const std::string& file, const glm::dvec3& offset,
                           const std::string& name) {
  nlohmann::json json = shippedConfigJson(file);
  for (auto& wall : json["walls"])
    for (const char* corner : {"lower_left", "lower_right", "upper_left"})
      for (int k = 0; k < 3; ++k) wall[corner][k] = wall[corner][k].get<double>() + offset[k];
  for (int k = 0; k < 3; ++k) json["reference"][k] = json["reference"][k].get<double>() + offset[k];
  json["name"] = name;
  return parseDisplayConfig(json, file);
}

void expectSameWalls(const DisplayConfig& actual, const DisplayConfig& expected) {
  ASSERT_EQ(actual.walls.size(), expected.walls.size());
  for (std::size_t i = 0; i < actual.walls.size(); ++i) {
    const Wall& a = actual.walls[i];
    const Wall& e = expected.walls[i];
    SCOPED_TRACE(e.name);
    EXPECT_EQ(a.name, e.name);
    EXPECT_TRUE(vecNear(a.lowerLeft, e.lowerLeft));
    EXPECT_TRUE(vecNear(a.lowerRight, e.lowerRight));
    EXPECT_TRUE(vecNear(a.upperLeft, e.upperLeft));
    EXPECT_EQ(a.width, e.width);
    EXPECT_EQ(a.height, e.height);
  }
  EXPECT_TRUE(vecNear(actual.reference, expected.reference));
  EXPECT_EQ(actual.eyeSeparation, expected.eyeSeparation);
  EXPECT_EQ(actual.source, expected.source);
  EXPECT_EQ(actual.hash, expected.hash);
}

template <typename Run>
void expectInvalid(Run run, std::initializer_list<std::string> fragments) {
  try {
    run();
    ADD_FAILURE() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidInput) << e.what();
    for (const std::string& fragment : fragments)
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos)
          << "message lacks \"" << fragment << "\": " << e.what();
  }
}

// One SGCT ProjectionPlane viewport inside a minimal cluster.
std::string sgctCluster(const std::string& viewports, const std::string& user =
                                                           R"({"pos": {"x": 0, "y": 0, "z": 0}})") {
  return R"({"version": 1, "masteraddress": "localhost", "nodes": [{"address": "localhost",
    "port": 20401, "windows": [{"name": "wall", "size": {"x": 3840, "y": 2160},
    "viewports": [)" + viewports + R"(]}]}], "users": [)" + user + "]}";
}

std::string plane(const char* ll, const char* ul, const char* ur, const std::string& extra = "") {
  return std::string(R"({)") + extra + R"("projection": {"type": "ProjectionPlane", "lowerleft": )" + ll +
         R"(, "upperleft": )" + ul + R"(, "upperright": )" + ur + "}}";
}

const char* kPvxFront = R"(<Machine Name="front" Geometry="1920x1920+0+0"
    LowerLeft="-1.5 -1.5 -1.5" LowerRight="1.5 -1.5 -1.5" UpperRight="1.5 1.5 -1.5"/>)";

std::string pvx(const std::string& machines) {
  return "<?xml version=\"1.0\" ?>\n<pvx>\n<Process Type=\"server\">\n" + machines +
         "\n</Process>\n</pvx>\n";
}

}  // namespace

TEST(DisplayImport, SgctJsonCaveHasTheWallsOfCave4InTheTrackerFrame) {
  ImportReport report;
  const DisplayConfig config = importDisplayConfig(imported("sgct-cave4.json"), {}, &report);
  EXPECT_EQ(report.format, DisplayFormat::SgctJson);
  EXPECT_EQ(config.name, "sgct-cave4");
  // SGCT's tracker frame has the floor at y = 0 and the default user 1.5 m above it.
  expectSameWalls(config, shippedMoved("cave4.json", {0, 1.5, 0}, "sgct-cave4"));
  // The GUI window's planar projection is no screen: skipped, and said so.
  ASSERT_EQ(report.notes.size(), 1u);
  EXPECT_NE(report.notes[0].find("nodes[0].windows[0].viewports[0]"), std::string::npos);
  EXPECT_NE(report.notes[0].find("PlanarProjection"), std::string::npos);
}

TEST(DisplayImport, SgctXmlGivesTheSameDisplayAsItsJson) {
  ImportOptions options;
  options.name = "lab";
  ImportReport report;
  const DisplayConfig fromXml = importDisplayConfig(imported("sgct-cave4.xml"), options, &report);
  EXPECT_EQ(report.format, DisplayFormat::SgctXml);
  ASSERT_EQ(report.notes.size(), 1u);  // the GUI window again
  EXPECT_NE(report.notes[0].find("sgct-cave4.xml:"), std::string::npos) << report.notes[0];
  expectSameWalls(fromXml, importDisplayConfig(imported("sgct-cave4.json"), options));
}

TEST(DisplayImport, ParaViewPvxIsCave3) {
  ImportOptions options;
  options.name = "cave3";
  ImportReport report;
  const DisplayConfig config = importDisplayConfig(imported("paraview-cave3.pvx"), options, &report);
  EXPECT_EQ(report.format, DisplayFormat::ParaViewPvx);
  EXPECT_TRUE(report.notes.empty());
  expectSameWalls(config, shippedConfig("cave3.json"));
}

TEST(DisplayImport, LoadDisplayConfigReadsEveryFormatAndDetectsIt) {
  EXPECT_EQ(detectDisplayFormat(imported("sgct-cave4.json")), DisplayFormat::SgctJson);
  EXPECT_EQ(detectDisplayFormat(imported("sgct-cave4.xml")), DisplayFormat::SgctXml);
  EXPECT_EQ(detectDisplayFormat(imported("paraview-cave3.pvx")), DisplayFormat::ParaViewPvx);
  EXPECT_EQ(detectDisplayFormat(configDir() / "cave5.json"), DisplayFormat::Confvis);
  EXPECT_EQ(loadDisplayConfig(imported("sgct-cave4.json")).hash,
            importDisplayConfig(imported("sgct-cave4.json")).hash);
  EXPECT_EQ(loadDisplayConfig(imported("paraview-cave3.pvx")).walls.size(), 3u);
  EXPECT_EQ(loadDisplayConfig(configDir() / "cave5.json").hash, shippedConfig("cave5.json").hash);
}

TEST(DisplayImport, FlatSgctScreenGetsTheHemisphereFacingIt) {
  // SGCT's 3DTV-style single screen, the geometry of configs/flat-wall.json.
  const std::string text = sgctCluster(plane(R"({"x": -1.5, "y": -0.84375, "z": -1.5})",
                                             R"({"x": -1.5, "y": 0.84375, "z": -1.5})",
                                             R"({"x": 1.5, "y": 0.84375, "z": -1.5})"),
                                       R"({"eyeseparation": 0.064, "pos": {"x": 0, "y": 0, "z": 0}})");
  ImportOptions options;
  options.name = "flat-wall";
  const DisplayConfig config = parseSgctJson(text, "tv.json", options);
  nlohmann::json expected = shippedConfigJson("flat-wall.json");
  expected["walls"][0]["name"] = "wall";  // SGCT names the window, not the screen
  expectSameWalls(config, parseDisplayConfig(expected, "flat-wall.json"));
  EXPECT_TRUE(vecNear(config.hemisphereAxis, {0, 0, -1}));
}

TEST(DisplayImport, SgctViewportsSplitTheirWindowAndRepeatedEyesAreSkipped) {
  // A 3840x2160 window split into two 1920x2160 viewports showing a front and a right screen,
  // plus a right-eye viewport repeating the front screen's corners.
  const std::string front = plane(R"({"x": -1, "y": -1, "z": -1})", R"({"x": -1, "y": 1, "z": -1})",
                                  R"({"x": 1, "y": 1, "z": -1})", R"("size": {"x": 0.5, "y": 1},)");
  const std::string right = plane(R"({"x": 1, "y": -1, "z": -1})", R"({"x": 1, "y": 1, "z": -1})",
                                  R"({"x": 1, "y": 1, "z": 1})",
                                  R"("pos": {"x": 0.5, "y": 0}, "size": {"x": 0.5, "y": 1},)");
  const std::string rightEye = plane(R"({"x": -1, "y": -1, "z": -1})", R"({"x": -1, "y": 1, "z": -1})",
                                     R"({"x": 1, "y": 1, "z": -1})", R"("eye": "right",)");
  ImportReport report;
  const DisplayConfig config =
      parseSgctJson(sgctCluster(front + "," + right + "," + rightEye), "split.json", {}, &report);
  ASSERT_EQ(config.walls.size(), 2u);
  EXPECT_EQ(config.walls[0].name, "wall-viewport0");
  EXPECT_EQ(config.walls[1].name, "wall-viewport1");
  for (const Wall& w : config.walls) {
    EXPECT_EQ(w.width, 1920);
    EXPECT_EQ(w.height, 2160);
  }
  // lower-right = lower-left + upper-right - upper-left
  EXPECT_TRUE(vecNear(config.walls[1].lowerRight, {1, -1, 1}));
  EXPECT_EQ(config.source, SourceField::FullSphere);  // two planes: not a flat wall
  ASSERT_EQ(report.notes.size(), 1u);
  EXPECT_NE(report.notes[0].find("viewports[2]"), std::string::npos) << report.notes[0];
  EXPECT_NE(report.notes[0].find("'wall-viewport0'"), std::string::npos) << report.notes[0];
}

TEST(DisplayImport, OptionsScaleFeetOverrideTheReferenceAndFillMissingResolutions) {
  // A 10 ft front wall in feet, without Geometry, eye separation given in feet too.
  const std::string text = pvx(R"(<EyeSeparation Value="0.21"/>
    <Machine Name="front" LowerLeft="-5 -5 -5" LowerRight="5 -5 -5" UpperRight="5 5 -5"/>)");
  ImportOptions options;
  options.scale = 0.3048;
  options.reference = glm::dvec3(0.0, 0.1, 0.0);
  options.fallbackResolution = std::pair{1400, 1050};
  const DisplayConfig config = parseParaViewPvx(text, "feet.pvx", options);
  ASSERT_EQ(config.walls.size(), 1u);
  EXPECT_TRUE(vecNear(config.walls[0].lowerLeft, glm::dvec3(-5, -5, -5) * 0.3048));
  EXPECT_TRUE(vecNear(config.walls[0].upperLeft, glm::dvec3(-5, 5, -5) * 0.3048));
  EXPECT_TRUE(vecNear(config.reference, {0.0, 0.1, 0.0}));
  EXPECT_DOUBLE_EQ(config.eyeSeparation, 0.21 * 0.3048);
  EXPECT_EQ(config.walls[0].width, 1400);
  EXPECT_EQ(config.walls[0].height, 1050);
  EXPECT_EQ(config.name, "feet");
}

TEST(DisplayImport, PvxUpperLeftFormAndMachinesOutsideAProcess) {
  // ParaView 6.1 drops <Process>; the older wiki form gives UpperLeft instead of UpperRight.
  const std::string text = R"(<pvx><Machine Name="front" Geometry="800x600+0+0"
      LowerLeft="-1.5 -1.5 -1.5" LowerRight="1.5 -1.5 -1.5" UpperLeft="-1.5 1.5 -1.5"/></pvx>)";
  const DisplayConfig config = parseParaViewPvx(text, "new.pvx");
  ASSERT_EQ(config.walls.size(), 1u);
  EXPECT_TRUE(vecNear(config.walls[0].upperLeft, {-1.5, 1.5, -1.5}));
  EXPECT_EQ(config.walls[0].width, 800);
  EXPECT_DOUBLE_EQ(config.eyeSeparation, 0.065);  // ParaView's default
}

TEST(DisplayImport, MalformedPvxNamesFileLineAndMachine) {
  expectInvalid([] { (void)parseParaViewPvx(pvx(R"(<Machine Name="left" Geometry="1x1+0+0"
      LowerLeft="-1.5 -1.5 1.5" UpperRight="-1.5 1.5 -1.5"/>)"), "lab.pvx"); },
                {"lab.pvx:4:", "<Machine Name=\"left\">", "'LowerRight' is missing"});
  // The typo of a real file: "0/05" for "0.05".
  expectInvalid([] { (void)parseParaViewPvx(pvx(R"(<Machine Name="floor" Geometry="1x1+0+0"
      LowerLeft="-1.13 -0.635 0.05" LowerRight="1.13 -0.635 0/05" UpperRight="1.13 -0.635 -1.22"/>)"),
                                            "lab.pvx"); },
                {"lab.pvx:4:", "floor", "LowerRight", "\"1.13 -0.635 0/05\""});
  expectInvalid([] { (void)parseParaViewPvx(pvx(R"(<Machine Name="front" Geometry="1920*1080"
      LowerLeft="-1.5 -1.5 -1.5" LowerRight="1.5 -1.5 -1.5" UpperRight="1.5 1.5 -1.5"/>)"), "lab.pvx"); },
                {"lab.pvx:4:", "front", "Geometry", "1920*1080"});
  expectInvalid([] { (void)parseParaViewPvx(pvx(R"(<Machine Name="front"
      LowerLeft="-1.5 -1.5 -1.5" LowerRight="1.5 -1.5 -1.5" UpperRight="1.5 1.5 -1.5"/>)"), "lab.pvx"); },
                {"lab.pvx:4:", "front", "Geometry", "--resolution"});
  expectInvalid([] { (void)parseParaViewPvx("<pvx>\n<Process>\n<Machine Name=\"a\">\n</pvx>", "lab.pvx"); },
                {"lab.pvx:4:", "invalid XML"});
  expectInvalid([] { (void)parseParaViewPvx("<Cluster/>", "lab.pvx"); }, {"lab.pvx:1:", "<pvx>"});
  expectInvalid([] { (void)parseParaViewPvx(pvx("<Machine Name=\"gui\"/>"), "lab.pvx"); },
                {"lab.pvx", "no <Machine> with"});
  // Geometry that is not a rectangle is caught by the display validation, naming the wall.
  expectInvalid([] { (void)parseParaViewPvx(pvx(R"(<Machine Name="front" Geometry="1x1+0+0"
      LowerLeft="-1.5 -1.5 -1.5" LowerRight="1.5 -1.5 -1.5" UpperRight="2.5 1.5 -1.5"/>)"), "lab.pvx"); },
                {"lab.pvx", "wall 'front'"});
  // Two machines on the same screen of different sizes overlap.
  expectInvalid([] { (void)parseParaViewPvx(pvx(std::string(kPvxFront) + R"(<Machine Name="inset"
      Geometry="1x1+0+0" LowerLeft="-1 -1 -1.5" LowerRight="1 -1 -1.5" UpperRight="1 1 -1.5"/>)"),
                                            "lab.pvx"); },
                {"lab.pvx", "front", "inset", "overlap"});
}

TEST(DisplayImport, MalformedSgctNamesFileAndElement) {
  const char* ll = R"({"x": -1, "y": -1, "z": -1})";
  const char* ul = R"({"x": -1, "y": 1, "z": -1})";
  expectInvalid([&] {
    (void)parseSgctJson(sgctCluster(R"({"projection": {"type": "ProjectionPlane", "lowerleft": )" +
                                    std::string(ll) + R"(, "upperleft": )" + ul + "}}"),
                        "lab.json");
  }, {"lab.json", "nodes[0].windows[0].viewports[0].projection", "'upperright'"});
  expectInvalid([&] {
    (void)parseSgctJson(sgctCluster(plane(ll, ul, R"({"x": "1", "y": 1, "z": -1})")), "lab.json");
  }, {"lab.json", "viewports[0].projection.upperright.x", "must be a number"});
  expectInvalid([] {
    (void)parseSgctJson(sgctCluster(R"({"projection": {"type": "FisheyeProjection"}})"), "lab.json");
  }, {"lab.json", "no viewport with a ProjectionPlane"});
  expectInvalid([] { (void)parseSgctJson("{\"nodes\": [", "lab.json"); }, {"lab.json", "invalid JSON"});
  expectInvalid([] { (void)parseSgctJson(R"({"version": 1})", "lab.json"); },
                {"lab.json", "'nodes' is required"});
  // The default user stands behind the screen: the validation names the wall.
  expectInvalid([&] {
    (void)parseSgctJson(sgctCluster(plane(ll, ul, R"({"x": 1, "y": 1, "z": -1})"),
                                    R"({"pos": {"x": 0, "y": 0, "z": -2}})"),
                        "lab.json");
  }, {"lab.json", "wall 'wall'"});
  expectInvalid([] {
    (void)parseSgctXml("<Cluster>\n<Node>\n<Window name=\"front\"><Size x=\"10\" y=\"10\"/>\n"
                       "<Viewport><Viewplane><Pos x=\"0\" y=\"0\" z=\"-1\"/>\n"
                       "<Pos x=\"0\" y=\"1\" z=\"-1\"/></Viewplane></Viewport>\n"
                       "</Window></Node></Cluster>", "old.xml");
  }, {"old.xml:4:", "<Viewplane>", "exactly 3 <Pos>", "got 2"});
  expectInvalid([] {
    (void)parseSgctXml("<Cluster><Node>\n<Window name=\"front\">\n<Viewport><Viewplane>"
                       "<Pos x=\"-1\" y=\"-1\" z=\"-1\"/><Pos x=\"-1\" y=\"1\" z=\"-1\"/>"
                       "<Pos x=\"1\" y=\"1\" z=\"-1\"/></Viewplane></Viewport></Window></Node></Cluster>",
                       "old.xml");
  }, {"old.xml:2:", "<Window name=\"front\">", "no <Size>"});
  expectInvalid([] {
    (void)parseSgctXml("<Cluster><User><Pos x=\"0\" y=\"one\" z=\"0\"/></User></Cluster>", "old.xml");
  }, {"old.xml:1:", "<Pos>", "'y'", "\"one\""});
}

TEST(DisplayImport, MissingFileIsFileNotFoundNamingThePath) {
  for (const char* name : {"/no/such/cave.pvx", "/no/such/cave.xml", "/no/such/cave.json"}) {
    try {
      (void)importDisplayConfig(name);
      ADD_FAILURE() << "expected an Error for " << name;
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::FileNotFound);
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}
