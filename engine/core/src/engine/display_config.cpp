#include "confvis/engine/display_config.hpp"
#include "confvis/engine/default_edge_length.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <tuple>
#include <utility>

#include "confvis/base/atomic_file.hpp"
#include "confvis/base/checksum.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/input_limits.hpp"
#include "confvis/base/json_text.hpp"
#include "confvis/engine/display_import.hpp"
#include "confvis/engine/display_surfaces.hpp"
#include "display_checks.hpp"

namespace confvis {

using nlohmann::json;

// ---- Wall geometry -------------------------------------------------------------------------

glm::dvec3 Wall::upperRight() const { return lowerRight + (upperLeft - lowerLeft); }
std::array<glm::dvec3, 4> Wall::corners() const {
  return {lowerLeft, lowerRight, upperRight(), upperLeft};
}
glm::dvec3 Wall::right() const { return glm::normalize(lowerRight - lowerLeft); }
glm::dvec3 Wall::up() const { return glm::normalize(upperLeft - lowerLeft); }
glm::dvec3 Wall::normal() const { return glm::normalize(glm::cross(right(), up())); }
double Wall::widthMetres() const { return glm::length(lowerRight - lowerLeft); }
double Wall::heightMetres() const { return glm::length(upperLeft - lowerLeft); }

glm::dvec3 Wall::pointAt(double s, double t) const {
  return lowerLeft + s * (lowerRight - lowerLeft) + t * (upperLeft - lowerLeft);
}

glm::dvec3 Wall::pixelCenter(int x, int y) const {
  const double s = (x + 0.5) / width;
  const double t = 1.0 - (y + 0.5) / height;
  return pointAt(s, t);
}

Wall Wall::litRectangle() const {
  const glm::dvec3 r = right(), u = up();
  Wall lit = *this;
  lit.lowerLeft = lowerLeft + bezel.left * r + bezel.bottom * u;
  lit.lowerRight = lowerRight - bezel.right * r + bezel.bottom * u;
  lit.upperLeft = upperLeft + bezel.left * r - bezel.top * u;
  lit.bezel = Bezel{};
  return lit;
}

const Wall& DisplayConfig::wall(const std::string& wallName) const {
  std::string known;
  for (const Wall& w : walls) {
    if (w.name == wallName) return w;
    known += (known.empty() ? "'" : ", '") + w.name + "'";
  }
  throw Error(ErrorCode::InvalidInput,
              "display '" + name + "' has no wall '" + wallName + "' (walls: " + known + ")");
}

// ---- JSON reading --------------------------------------------------------------------------
namespace {

// Limits beyond which a value is a typo, not a display.
constexpr int kMaxWallPixels = 65536;
constexpr int kMinCubeResolution = 8;
constexpr int kMaxCubeResolution = 8192;

// Reads the members of one JSON object; `where` ("cave5.json: wall 'front'") prefixes errors.
class ObjectReader {
 public:
  ObjectReader(const json& object, std::string where) : object_(object), where_(std::move(where)) {
    if (!object_.is_object()) fail("must be a JSON object, got " + describe(object_));
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw Error(ErrorCode::InvalidInput, where_ + ": " + what);
  }
  [[noreturn]] void failKey(const char* key, const std::string& what) const {
    fail("'" + std::string(key) + "' " + what);
  }
  const std::string& where() const { return where_; }

  void rejectUnknownKeys(std::initializer_list<const char*> known) const {
    for (const auto& item : object_.items()) {
      bool isKnown = false;
      std::string list;
      for (const char* k : known) {
        isKnown = isKnown || item.key() == k;
        list += (list.empty() ? "" : ", ") + std::string(k);
      }
      if (!isKnown) fail("unknown key '" + item.key() + "' (allowed: " + list + ")");
    }
  }

  bool has(const char* key) const { return object_.contains(key); }

  const json& required(const char* key) const {
    if (!has(key)) failKey(key, "is required but missing");
    return object_.at(key);
  }

  std::string string(const char* key) const {
    const json& v = required(key);
    if (!v.is_string()) failKey(key, "must be a string, got " + describe(v));
    return v.get<std::string>();
  }

  double number(const char* key) const { return finiteNumber(key, required(key)); }
  double number(const char* key, double fallback) const {
    return has(key) ? number(key) : fallback;
  }

  int integer(const char* key, int fallback) const {
    if (!has(key)) return fallback;
    return integerValue(key, object_.at(key));
  }

  glm::dvec3 vec3(const char* key) const {
    const json& v = required(key);
    if (!v.is_array() || v.size() != 3) failKey(key, "must be an array of 3 numbers");
    return {finiteNumber(key, v[0]), finiteNumber(key, v[1]), finiteNumber(key, v[2])};
  }
  glm::dvec3 vec3(const char* key, const glm::dvec3& fallback) const {
    return has(key) ? vec3(key) : fallback;
  }

  std::pair<int, int> intPair(const char* key) const {
    const json& v = required(key);
    if (!v.is_array() || v.size() != 2) failKey(key, "must be an array of 2 integers");
    return {integerValue(key, v[0]), integerValue(key, v[1])};
  }

 private:
  static std::string describe(const json& v) { return std::string(v.type_name()); }

  double finiteNumber(const char* key, const json& v) const {
    if (!v.is_number()) failKey(key, "must be a number, got " + describe(v));
    const double x = v.get<double>();
    if (!std::isfinite(x)) failKey(key, "must be finite, got " + std::to_string(x));
    return x;
  }

  int integerValue(const char* key, const json& v) const {
    if (!v.is_number_integer()) failKey(key, "must be an integer, got " + v.dump());
    constexpr auto kMax = std::numeric_limits<int>::max();
    constexpr auto kMin = std::numeric_limits<int>::min();
    const bool outOfRange = v.is_number_unsigned()
                                ? v.get<std::uint64_t>() > static_cast<std::uint64_t>(kMax)
                                : v.get<std::int64_t>() < kMin || v.get<std::int64_t>() > kMax;
    if (outOfRange) failKey(key, "is out of range: " + v.dump());
    return v.get<int>();
  }

  const json& object_;
  std::string where_;
};

Bezel readBezel(const ObjectReader& wallReader, const json& wallJson) {
  if (!wallReader.has("bezel")) return {};
  const ObjectReader r(wallJson.at("bezel"), wallReader.where() + " bezel");
  r.rejectUnknownKeys({"left", "right", "bottom", "top"});
  Bezel b{r.number("left", 0.0), r.number("right", 0.0), r.number("bottom", 0.0),
          r.number("top", 0.0)};
  for (const auto& [key, value] : {std::pair{"left", b.left}, std::pair{"right", b.right},
                                   std::pair{"bottom", b.bottom}, std::pair{"top", b.top}})
    if (value < 0.0) r.failKey(key, "must not be negative, got " + std::to_string(value));
  return b;
}

Wall readWall(const json& wallJson, std::size_t index, const std::string& sourceName) {
  // Name the wall by index until its name is known, then by name.
  const ObjectReader byIndex(wallJson, sourceName + ": walls[" + std::to_string(index) + "]");
  Wall wall;
  wall.name = byIndex.string("name");
  if (wall.name.empty()) byIndex.failKey("name", "must not be empty");
  requireFileNameSafe(wall.name, byIndex.where() + ": wall name");  // it names output files
  const ObjectReader r(wallJson, sourceName + ": wall '" + wall.name + "'");
  r.rejectUnknownKeys({"name", "lower_left", "lower_right", "upper_left", "resolution", "bezel",
                       "window", "stereo_output", "node", "preview"});
  wall.lowerLeft = r.vec3("lower_left");
  wall.lowerRight = r.vec3("lower_right");
  wall.upperLeft = r.vec3("upper_left");
  std::tie(wall.width, wall.height) = r.intPair("resolution");
  if (wall.width <= 0 || wall.height <= 0 || wall.width > kMaxWallPixels ||
      wall.height > kMaxWallPixels)
    r.failKey("resolution", "must be between 1 and " + std::to_string(kMaxWallPixels) +
                                " pixels per side, got " + wallJson.at("resolution").dump());
  wall.bezel = readBezel(r, wallJson);
  if (r.has("node")) {  // a host name, or a rank number (cluster.hpp)
    const json& node = wallJson.at("node");
    if (node.is_number_integer() && node.get<std::int64_t>() >= 0)
      wall.node = std::to_string(node.get<std::int64_t>());
    else if (node.is_string() && !node.get<std::string>().empty()) wall.node = node;
    else r.failKey("node", "must be a host name or a rank number (>= 0), got " + node.dump());
  }
  if (r.has("preview")) {
    const json& preview = wallJson.at("preview");
    if (!preview.is_boolean()) r.failKey("preview", "must be true or false, got " + preview.dump());
    wall.preview = preview.get<bool>();
  }
  wall.output = detail::readWallOutput(wallJson, r.where());
  return wall;
}

void readSource(const ObjectReader& top, const json& root, DisplayConfig& config) {
  if (!top.has("source")) return;
  const ObjectReader r(root.at("source"), top.where() + ": source");
  r.rejectUnknownKeys({"field", "axis"});
  if (r.has("field")) {
    const std::string field = r.string("field");
    if (field == "sphere") config.source = SourceField::FullSphere;
    else if (field == "hemisphere") config.source = SourceField::Hemisphere;
    else r.failKey("field", "must be \"sphere\" or \"hemisphere\", got \"" + field + "\"");
  }
  const glm::dvec3 axis = r.vec3("axis", config.hemisphereAxis);
  if (glm::length(axis) < detail::kLengthTolerance) r.failKey("axis", "must not have zero length");
  config.hemisphereAxis = glm::normalize(axis);
}

json vecJson(const glm::dvec3& v) { return json::array({v.x, v.y, v.z}); }

EdgeBlend readEdgeBlend(const ObjectReader& top, const json& root) {
  EdgeBlend blend;
  if (!top.has("edge_blend")) return blend;
  const ObjectReader r(root.at("edge_blend"), top.where() + ": edge_blend");
  r.rejectUnknownKeys({"gamma"});
  blend.enabled = true;
  blend.gamma = r.number("gamma", blend.gamma);
  if (!(blend.gamma >= 0.1 && blend.gamma <= 10.0))
    r.failKey("gamma", "must be between 0.1 and 10 (a projector's response, 2.2 typical), got " +
                           std::to_string(blend.gamma));
  return blend;
}

}  // namespace

DisplayConfig parseDisplayConfig(const json& root, const std::string& sourceName) {
  const ObjectReader top(root, sourceName);
  top.rejectUnknownKeys({"name", "reference", "source", "edge_length", "cube_resolution",
                         "stereo", "tracking", "edge_blend", "walls"});
  DisplayConfig config;
  config.name = top.string("name");
  if (config.name.empty()) top.failKey("name", "must not be empty");
  requireFileNameSafe(config.name, sourceName + ": display name");  // it names output folders
  config.reference = top.vec3("reference", config.reference);
  for (int i = 0; i < 3; ++i)
    if (!(std::abs(config.reference[i]) <= detail::kMaxCoordinateMetres))
      top.failKey("reference", "must lie within " +
                                   std::to_string(static_cast<int>(detail::kMaxCoordinateMetres)) +
                                   " m of the origin on every axis, got " +
                                   std::to_string(config.reference[i]));
  readSource(top, root, config);
  config.edgeLength = top.number("edge_length", config.edgeLength);
  if (config.edgeLength <= 0.0)
    top.failKey("edge_length", "must be positive, got " + std::to_string(config.edgeLength));
  config.cubeResolution = top.integer("cube_resolution", config.cubeResolution);
  if (config.cubeResolution < kMinCubeResolution || config.cubeResolution > kMaxCubeResolution)
    top.failKey("cube_resolution", "must be between " + std::to_string(kMinCubeResolution) +
                                       " and " + std::to_string(kMaxCubeResolution) + ", got " +
                                       std::to_string(config.cubeResolution));
  if (top.has("stereo")) {
    const ObjectReader stereo(root.at("stereo"), sourceName + ": stereo");
    stereo.rejectUnknownKeys({"eye_separation"});
    config.eyeSeparation = stereo.number("eye_separation", config.eyeSeparation);
    if (config.eyeSeparation < 0.0)
      stereo.failKey("eye_separation", "must not be negative");
  }

  if (top.has("tracking"))
    config.tracking = parseTrackingConfig(root.at("tracking"), sourceName + ": tracking");

  config.edgeBlend = readEdgeBlend(top, root);

  const json& walls = top.required("walls");
  if (!walls.is_array()) top.failKey("walls", "must be an array of walls");
  if (walls.empty()) top.failKey("walls", "must hold at least one wall");
  for (std::size_t i = 0; i < walls.size(); ++i) {
    config.walls.push_back(readWall(walls[i], i, sourceName));
    detail::checkWallShape(config.walls.back(), sourceName);
    detail::checkFacesReference(config.walls.back(), config.reference, sourceName);
  }
  detail::checkWallSet(config, sourceName);
  if (!top.has("edge_length"))  // overlapping projector walls count once, as their surface
    config.edgeLength = defaultEdgeLength(surfaceConfig(config).walls, config.reference);
  json hashed = detail::withoutWallOutputs(toJson(config));
  hashed.erase("tracking");  // the tracker does not change the map: its edits keep the bake cache
  hashed.erase("edge_blend");  // nor does the blend of overlapping projectors
  config.hash = fnv1a64Hex(hashed.dump());
  return config;
}

DisplayConfig loadDisplayConfig(const std::filesystem::path& path) {
  // SGCT and ParaView descriptions load directly, with default import options.
  if (detectDisplayFormat(path) != DisplayFormat::Confvis) return importDisplayConfig(path);
  const std::string text = readTextFile(path);  // Error(FileNotFound) naming the path
  return parseDisplayConfig(parseJsonText(text, path.string()), path.string());
}

json toJson(const DisplayConfig& config) {
  json walls = json::array();
  for (const Wall& w : config.walls) {
    walls.push_back({{"name", w.name},
                     {"lower_left", vecJson(w.lowerLeft)},
                     {"lower_right", vecJson(w.lowerRight)},
                     {"upper_left", vecJson(w.upperLeft)},
                     {"resolution", json::array({w.width, w.height})},
                     {"bezel",
                      {{"left", w.bezel.left},
                       {"right", w.bezel.right},
                       {"bottom", w.bezel.bottom},
                       {"top", w.bezel.top}}}});
    if (!w.node.empty()) walls.back()["node"] = w.node;
    if (w.preview) walls.back()["preview"] = true;  // only when set: older hashes stay valid
    detail::writeWallOutput(w.output, walls.back());
  }
  const char* field = config.source == SourceField::Hemisphere ? "hemisphere" : "sphere";
  json result = {{"name", config.name},
          {"reference", vecJson(config.reference)},
          {"source", {{"field", field}, {"axis", vecJson(config.hemisphereAxis)}}},
          {"edge_length", config.edgeLength},
          {"cube_resolution", config.cubeResolution},
          {"stereo", {{"eye_separation", config.eyeSeparation}}},
          {"tracking", toJson(config.tracking)},
          {"walls", walls}};
  if (config.edgeBlend.enabled) result["edge_blend"] = {{"gamma", config.edgeBlend.gamma}};
  return result;
}

}  // namespace confvis
