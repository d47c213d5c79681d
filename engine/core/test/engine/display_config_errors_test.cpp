// Every invalid display config is rejected with one Error whose message names the culprit.
// Each case starts from a valid shipped config and breaks exactly one thing.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <unistd.h>

#include "confvis/base/error.hpp"
#include "confvis/engine/display_config.hpp"
#include "display_test_support.hpp"

using namespace confvis;
using confvis::testing::shippedConfigJson;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

// Asserts that `run` throws Error(code) whose message contains every fragment.
template <typename Run>
void expectError(Run run, ErrorCode code, std::initializer_list<std::string> fragments) {
  try {
    run();
    ADD_FAILURE() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), code) << e.what();
    for (const std::string& fragment : fragments)
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos)
          << "message lacks \"" << fragment << "\": " << e.what();
  }
}

void expectInvalid(const json& config, std::initializer_list<std::string> fragments) {
  expectError([&] { (void)parseDisplayConfig(config, "broken.json"); }, ErrorCode::InvalidInput,
              fragments);
}

json cave(const char* file = "cave6.json") { return shippedConfigJson(file); }

// The wall named `name` inside a config's JSON, for in-place edits.
json& wallJson(json& config, const std::string& name) {
  for (json& w : config["walls"])
    if (w["name"] == name) return w;
  throw std::logic_error("no wall " + name);
}

fs::path writeTemp(const std::string& name, const std::string& text) {
  const fs::path path = fs::temp_directory_path() / (name + std::to_string(getpid()) + ".json");
  std::ofstream(path) << text;
  return path;
}

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

TEST(DisplayConfigErrors, MissingFileIsFileNotFoundNamingThePath) {
  const fs::path path = "/nonexistent/confvis/no-such-display.json";
  expectError([&] { (void)loadDisplayConfig(path); }, ErrorCode::FileNotFound,
              {"no-such-display.json"});
}

TEST(DisplayConfigErrors, JsonSyntaxErrorNamesTheFile) {
  std::string text = cave().dump(2);
  text.erase(text.rfind('}'));  // truncated file
  const fs::path path = writeTemp("confvis_truncated", text);
  expectError([&] { (void)loadDisplayConfig(path); }, ErrorCode::InvalidInput,
              {path.string(), "invalid JSON"});
  fs::remove(path);
}

TEST(DisplayConfigErrors, OverflowingNumberNamesTheFile) {
  const fs::path path = writeTemp("confvis_overflow", R"({"name": "x", "edge_length": 1e999})");
  expectError([&] { (void)loadDisplayConfig(path); }, ErrorCode::InvalidInput,
              {path.string(), "1e999"});
  fs::remove(path);
}

TEST(DisplayConfigErrors, UnknownKeysAreNamedWithTheirPlace) {
  json top = cave();
  top["refrence"] = {0, 0, 0};
  expectInvalid(top, {"broken.json", "unknown key 'refrence'", "reference"});

  json inWall = cave();
  wallJson(inWall, "left")["lowerleft"] = {0, 0, 0};
  expectInvalid(inWall, {"wall 'left'", "unknown key 'lowerleft'"});

  json inBezel = cave();
  wallJson(inBezel, "floor")["bezel"] = {{"inner", 0.01}};
  expectInvalid(inBezel, {"wall 'floor' bezel", "unknown key 'inner'"});

  json inSource = cave();
  inSource["source"]["centre"] = {0, 0, -1};
  expectInvalid(inSource, {"source", "unknown key 'centre'"});

  json inStereo = cave();
  inStereo["stereo"]["ipd"] = 0.064;
  expectInvalid(inStereo, {"stereo", "unknown key 'ipd'"});
}

TEST(DisplayConfigErrors, WrongTypesNameTheKey) {
  json reference = cave();
  reference["reference"] = "origin";
  expectInvalid(reference, {"'reference'", "array of 3 numbers"});

  json shortCorner = cave();
  wallJson(shortCorner, "back")["upper_left"] = {1.5, 1.5};
  expectInvalid(shortCorner, {"wall 'back'", "'upper_left'", "array of 3 numbers"});

  json fractionalPixels = cave();
  wallJson(fractionalPixels, "right")["resolution"] = {1920.5, 1920};
  expectInvalid(fractionalPixels, {"wall 'right'", "'resolution'", "integer"});

  json stringCoordinate = cave();
  wallJson(stringCoordinate, "front")["lower_left"][2] = "-1.5";
  expectInvalid(stringCoordinate, {"wall 'front'", "'lower_left'", "must be a number"});

  json wallsObject = cave();
  wallsObject["walls"] = {{"front", 1}};
  expectInvalid(wallsObject, {"'walls'", "array"});

  json numericName = cave();
  numericName["walls"][2]["name"] = 7;
  expectInvalid(numericName, {"walls[2]", "'name'", "string"});

  json bezelString = cave();
  wallJson(bezelString, "front")["bezel"] = "thin";
  expectInvalid(bezelString, {"wall 'front' bezel", "JSON object"});

  json notAnObject = json::array({1, 2});
  expectInvalid(notAnObject, {"broken.json", "JSON object"});
}

TEST(DisplayConfigErrors, MissingRequiredFieldsAreNamed) {
  json noName = cave();
  noName.erase("name");
  expectInvalid(noName, {"'name'", "required"});

  json noWalls = cave();
  noWalls.erase("walls");
  expectInvalid(noWalls, {"'walls'", "required"});

  json emptyWalls = cave();
  emptyWalls["walls"] = json::array();
  expectInvalid(emptyWalls, {"'walls'", "at least one"});

  json noCorner = cave();
  wallJson(noCorner, "ceiling").erase("lower_right");
  expectInvalid(noCorner, {"wall 'ceiling'", "'lower_right'", "required"});

  json noResolution = cave();
  wallJson(noResolution, "left").erase("resolution");
  expectInvalid(noResolution, {"wall 'left'", "'resolution'", "required"});

  json noWallName = cave();
  noWallName["walls"][3].erase("name");
  expectInvalid(noWallName, {"walls[3]", "'name'", "required"});
}

TEST(DisplayConfigErrors, DuplicateWallNamesAreNamed) {
  json j = cave();
  wallJson(j, "back")["name"] = "left";
  expectInvalid(j, {"'left'", "more than once"});
}

TEST(DisplayConfigErrors, DegenerateWallsAreNamed) {
  json zeroWidth = cave();
  wallJson(zeroWidth, "right")["lower_right"] = wallJson(zeroWidth, "right")["lower_left"];
  expectInvalid(zeroWidth, {"wall 'right'", "degenerate", "width"});

  json zeroHeight = cave();
  wallJson(zeroHeight, "front")["upper_left"] = {-1.5, -1.5 + 1e-8, -1.5};
  expectInvalid(zeroHeight, {"wall 'front'", "degenerate", "height"});

  json skewed = cave();
  wallJson(skewed, "front")["upper_left"] = {-1.49, 1.5, -1.5};  // a parallelogram
  expectInvalid(skewed, {"wall 'front'", "right angle"});
}

TEST(DisplayConfigErrors, NonPositiveOrAbsurdResolutionsAreNamed) {
  for (const json& resolution : {json{0, 1920}, json{1920, -1}, json{100000, 1920}}) {
    json j = cave();
    wallJson(j, "floor")["resolution"] = resolution;
    expectInvalid(j, {"wall 'floor'", "'resolution'", resolution.dump()});
  }
}

TEST(DisplayConfigErrors, BezelsMustLeaveALitArea) {
  json tooWide = cave();
  wallJson(tooWide, "back")["bezel"] = {{"left", 1.5}, {"right", 1.5}};
  expectInvalid(tooWide, {"wall 'back'", "no lit area", "left + right"});

  json tooTall = cave();
  wallJson(tooTall, "back")["bezel"] = {{"bottom", 2.0}, {"top", 1.2}};
  expectInvalid(tooTall, {"wall 'back'", "no lit area", "bottom + top"});

  json negative = cave();
  wallJson(negative, "back")["bezel"] = {{"top", -0.01}};
  expectInvalid(negative, {"wall 'back' bezel", "'top'", "negative"});
}

TEST(DisplayConfigErrors, WallFacingAwayFromTheReferenceIsNamed) {
  // Mirror the left wall: the same rectangle with its corners given as seen from outside.
  json j = cave();
  json& left = wallJson(j, "left");
  const json lowerLeft = left["lower_left"], lowerRight = left["lower_right"];
  left["lower_left"] = lowerRight;
  left["lower_right"] = lowerLeft;
  left["upper_left"] = {-1.5, 1.5, -1.5};
  expectInvalid(j, {"wall 'left'", "faces away"});
}

TEST(DisplayConfigErrors, ReferenceOnAWallPlaneIsNamed) {
  json j = cave("flat-wall.json");
  j["reference"] = {2.0, 0.0, -1.5};  // in the plane, beside the screen
  expectInvalid(j, {"wall 'screen'", "reference point in its plane"});
}

TEST(DisplayConfigErrors, ReferenceOutsideTheDisplayHullIsNamed) {
  json j = cave("cave5.json");
  j["reference"] = {0.0, 0.0, -2.0};  // in front of the front wall, outside the cube
  expectInvalid(j, {"wall 'front'", "outside the display"});
}

TEST(DisplayConfigErrors, OverlappingCoplanarWallsAreNamed) {
  // Shifted sideways and up: the two overlap on one plane (projectors may) but their union is no
  // rectangle, so they form no display surface (display_surfaces.hpp).
  json j = cave("flat-wall.json");
  json second = j["walls"][0];
  second["name"] = "shifted";
  for (const char* corner : {"lower_left", "lower_right", "upper_left"}) {
    second[corner][0] = second[corner][0].get<double>() + 1.0;
    second[corner][1] = second[corner][1].get<double>() + 0.2;
  }
  j["walls"].push_back(second);
  expectInvalid(j, {"'screen'", "'shifted'", "overlap", "rectangle"});
}

TEST(DisplayConfigErrors, CrossingWallsAreNamed) {
  json j = cave("flat-wall.json");
  // A side panel in the plane x = 0.5 that pierces the screen (z = -1.5) from behind.
  j["walls"].push_back({{"name", "blade"},
                        {"lower_left", {0.5, -0.5, -2.5}},
                        {"lower_right", {0.5, -0.5, -0.5}},
                        {"upper_left", {0.5, 0.5, -2.5}},
                        {"resolution", {100, 100}}});
  expectInvalid(j, {"'screen'", "'blade'", "overlap"});
}

TEST(DisplayConfigErrors, WallsMeetingAtAnEdgeOrCornerOrTouchingAreAccepted) {
  json j = cave("flat-wall.json");
  // Corner contact: a coplanar tile diagonally above-right of the screen.
  j["walls"].push_back({{"name", "corner"},
                        {"lower_left", {1.5, 0.84375, -1.5}},
                        {"lower_right", {2.5, 0.84375, -1.5}},
                        {"upper_left", {1.5, 1.5, -1.5}},
                        {"resolution", {100, 100}}});
  // T contact: a side panel standing on the screen's face, ending at it.
  j["walls"].push_back({{"name", "fin"},
                        {"lower_left", {0.5, -0.5, -1.5}},
                        {"lower_right", {0.5, -0.5, -0.5}},
                        {"upper_left", {0.5, 0.5, -1.5}},
                        {"resolution", {100, 100}}});
  EXPECT_EQ(parseDisplayConfig(j, "touching").walls.size(), 3u);
}

TEST(DisplayConfigErrors, NonFiniteNumbersAreNamed) {
  json reference = cave();
  reference["reference"][1] = kInf;
  expectInvalid(reference, {"'reference'", "finite"});

  json corner = cave();
  wallJson(corner, "ceiling")["upper_left"][0] = std::nan("");
  expectInvalid(corner, {"wall 'ceiling'", "'upper_left'", "finite"});

  json bezel = cave();
  wallJson(bezel, "front")["bezel"] = {{"left", kInf}};
  expectInvalid(bezel, {"wall 'front' bezel", "'left'", "finite"});
}

TEST(DisplayConfigErrors, GlobalSettingsOutOfRangeAreNamed) {
  for (const double edge : {0.0, -0.2}) {
    json j = cave();
    j["edge_length"] = edge;
    expectInvalid(j, {"'edge_length'", "positive"});
  }
  for (const int resolution : {4, 16384}) {
    json j = cave();
    j["cube_resolution"] = resolution;
    expectInvalid(j, {"'cube_resolution'", std::to_string(resolution)});
  }
  json axis = cave("flat-wall.json");
  axis["source"]["axis"] = {0, 0, 0};
  expectInvalid(axis, {"source", "'axis'", "zero length"});

  json field = cave();
  field["source"]["field"] = "cone";
  expectInvalid(field, {"source", "'field'", "cone"});

  json eyes = cave();
  eyes["stereo"]["eye_separation"] = -0.06;
  expectInvalid(eyes, {"stereo", "'eye_separation'"});
}
