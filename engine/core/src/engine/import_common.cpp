#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <filesystem>
#include <sstream>

#include "confvis/base/error.hpp"
#include "confvis/engine/display_surfaces.hpp"
#include "import_parts.hpp"

namespace confvis::detail {

using nlohmann::json;

namespace {

// Corners equal to this many file units are the same corner (hand-written files repeat a wall
// for the second eye with the very same numbers).
constexpr double kSameCorner = 1e-9;
// Walls whose planes agree this closely make a flat wall (metres; unit normals).
constexpr double kCoplanar = 1e-6;

json vecJson(const glm::dvec3& v) { return json::array({v.x, v.y, v.z}); }

bool sameCorners(const ImportedWall& a, const ImportedWall& b) {
  return glm::length(a.lowerLeft - b.lowerLeft) <= kSameCorner &&
         glm::length(a.lowerRight - b.lowerRight) <= kSameCorner &&
         glm::length(a.upperLeft - b.upperLeft) <= kSameCorner;
}

// right x up, unnormalised: its length is the wall's area; zero for a degenerate wall.
glm::dvec3 areaNormal(const ImportedWall& w) {
  return glm::cross(w.lowerRight - w.lowerLeft, w.upperLeft - w.lowerLeft);
}

bool allCoplanar(const std::vector<ImportedWall>& walls) {
  const glm::dvec3 n0 = areaNormal(walls.front());
  if (!(glm::length(n0) > 0.0)) return false;
  const glm::dvec3 unit0 = glm::normalize(n0);
  const double offset0 = glm::dot(unit0, walls.front().lowerLeft);
  return std::all_of(walls.begin(), walls.end(), [&](const ImportedWall& w) {
    const glm::dvec3 n = areaNormal(w);
    if (!(glm::length(n) > 0.0)) return false;
    const glm::dvec3 unit = glm::normalize(n);
    return glm::length(unit - unit0) <= kCoplanar &&
           std::abs(glm::dot(unit0, w.lowerLeft) - offset0) <= kCoplanar;
  });
}

// The direction from the viewer towards the walls: area-weighted mean of -normal.
glm::dvec3 hemisphereAxis(const std::vector<ImportedWall>& walls, const std::string& sourceName) {
  glm::dvec3 sum(0.0);
  for (const ImportedWall& w : walls) sum -= areaNormal(w);
  if (!(glm::length(sum) > 1e-12))
    throw Error(ErrorCode::InvalidInput,
                sourceName + ": the walls face every way, so no hemisphere faces them; import "
                             "with the full sphere as source");
  return glm::normalize(sum);
}

void makeNamesUnique(std::vector<ImportedWall>& walls, const std::string& sourceName,
                     std::vector<std::string>& notes) {
  for (std::size_t i = 0; i < walls.size(); ++i) {
    auto taken = [&](const std::string& name) {
      for (std::size_t j = 0; j < walls.size(); ++j)
        if (j != i && walls[j].name == name) return true;
      return false;
    };
    bool clash = false;
    for (std::size_t j = 0; j < i; ++j) clash = clash || walls[j].name == walls[i].name;
    if (!clash) continue;
    std::string renamed;
    for (int k = 2; renamed.empty() || taken(renamed); ++k)
      renamed = walls[i].name + "-" + std::to_string(k);
    notes.push_back(sourceName + ": " + walls[i].element + " repeats the name '" + walls[i].name +
                    "'; imported as '" + renamed + "'");
    walls[i].name = renamed;
  }
}


// Drops the windows named in `names`; a name matching none is an error listing the windows.
void skipWindows(ImportedDisplay& display, const std::vector<std::string>& names,
                 const std::string& sourceName) {
  for (const std::string& name : names) {
    const auto matches = [&](const ImportedWall& w) { return w.name == name; };
    if (std::none_of(display.walls.begin(), display.walls.end(), matches)) {
      std::string known;
      for (const ImportedWall& w : display.walls) known += (known.empty() ? "'" : ", '") + w.name + "'";
      throw Error(ErrorCode::InvalidInput, sourceName + ": skipped window '" + name +
                                               "' is not in the file (windows: " + known + ")");
    }
    for (const ImportedWall& w : display.walls)
      if (matches(w))
        display.notes.push_back(sourceName + ": " + w.element + " ('" + name +
                                "') skipped as asked");
    std::erase_if(display.walls, matches);
  }
}

// Metres per file unit when none is given: 1, or 0.001 for a display that spans more than
// kMillimetreSpan units (no CAVE or wall is 100 m across; SGCT files in millimetres are common).
constexpr double kMillimetreSpan = 100.0;
constexpr double kLargestMetres = 100.0;

double unitScale(const std::vector<ImportedWall>& walls, const std::string& sourceName,
                 std::vector<std::string>& notes) {
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (const ImportedWall& w : walls)
    for (const glm::dvec3& p : {w.lowerLeft, w.lowerRight, w.upperLeft,
                                w.lowerRight + w.upperLeft - w.lowerLeft}) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  const double span = glm::length(hi - lo);
  if (!(span > kMillimetreSpan)) return 1.0;
  char text[96];
  std::snprintf(text, sizeof text, "%.6g", span);
  if (span * 0.001 > kLargestMetres)
    throw Error(ErrorCode::InvalidInput,
                sourceName + ": the walls span " + text + " file units, too large for metres or "
                             "millimetres; give the unit with --scale (metres per file unit, e.g. "
                             "0.01 for centimetres)");
  notes.push_back(sourceName + ": the walls span " + text + " file units, so the file is read as "
                  "millimetres and converted to metres (--scale 1 keeps metres, --scale S sets "
                  "another unit)");
  return 0.001;
}

// A window covering two or more other walls on their plane is an operator's preview of them
// (SGCT masters often span the whole projection wall): imported with "preview": true.
void markPreviews(std::vector<ImportedWall>& walls, const std::string& sourceName,
                  std::vector<std::string>& notes) {
  auto asWall = [](const ImportedWall& w) {
    Wall wall;
    wall.lowerLeft = w.lowerLeft, wall.lowerRight = w.lowerRight, wall.upperLeft = w.upperLeft;
    return wall;
  };
  auto degenerate = [](const ImportedWall& w) {
    return !(glm::length(glm::cross(w.lowerRight - w.lowerLeft, w.upperLeft - w.lowerLeft)) > 0.0);
  };
  for (ImportedWall& outer : walls) {
    if (degenerate(outer)) continue;  // validation names it
    std::string covered;
    int count = 0;
    for (const ImportedWall& inner : walls)
      if (&inner != &outer && !degenerate(inner) && detail::wallCovers(asWall(outer), asWall(inner)))
        ++count, covered += (covered.empty() ? "'" : ", '") + inner.name + "'";
    if (count < 2) continue;
    outer.preview = true;
    notes.push_back(sourceName + ": " + outer.element + " ('" + outer.name + "') covers walls " +
                    covered + " on their plane: imported as a preview window (rendered, no display "
                    "surface of its own); --skip-window " + outer.name + " leaves it out");
  }
}

}  // namespace

DisplayConfig finishImport(ImportedDisplay display, const std::string& sourceName,
                           const ImportOptions& options, ImportReport* report) {
  if (options.scale && !(std::isfinite(*options.scale) && *options.scale > 0.0))
    throw Error(ErrorCode::InvalidInput, sourceName + ": import scale must be a positive number, got " +
                                             std::to_string(*options.scale));
  skipWindows(display, options.skipWindows, sourceName);
  // Second-eye viewports repeat a wall exactly: keep the first.
  std::vector<ImportedWall> walls;
  for (ImportedWall& w : display.walls) {
    const auto same = std::find_if(walls.begin(), walls.end(),
                                   [&](const ImportedWall& kept) { return sameCorners(kept, w); });
    if (same != walls.end()) {
      display.notes.push_back(sourceName + ": " + w.element + " repeats the corners of wall '" +
                              same->name + "' (another eye or window on the same screen); skipped");
      continue;
    }
    walls.push_back(std::move(w));
  }
  if (walls.empty())
    throw Error(ErrorCode::InvalidInput, sourceName + ": describes no walls");
  makeNamesUnique(walls, sourceName, display.notes);

  const double s = options.scale ? *options.scale : unitScale(walls, sourceName, display.notes);
  for (ImportedWall& w : walls) {
    w.lowerLeft *= s;
    w.lowerRight *= s;
    w.upperLeft *= s;
  }
  markPreviews(walls, sourceName, display.notes);
  const glm::dvec3 reference = options.reference.value_or(display.viewer.value_or(glm::dvec3(0.0)) * s);

  SourceField source = SourceField::FullSphere;
  if (options.source) source = *options.source;
  else if (allCoplanar(walls)) source = SourceField::Hemisphere;
  json sourceJson = {{"field", source == SourceField::Hemisphere ? "hemisphere" : "sphere"}};
  if (source == SourceField::Hemisphere) sourceJson["axis"] = vecJson(hemisphereAxis(walls, sourceName));

  std::string name = options.name;
  if (name.empty()) name = std::filesystem::path(sourceName).stem().string();
  json config = {{"name", name}, {"reference", vecJson(reference)}, {"source", sourceJson},
                 {"walls", json::array()}};
  if (options.edgeBlendGamma) config["edge_blend"] = {{"gamma", *options.edgeBlendGamma}};
  if (display.eyeSeparation)
    config["stereo"] = {{"eye_separation", *display.eyeSeparation * s}};
  else if (display.eyeSeparationMetres)
    config["stereo"] = {{"eye_separation", *display.eyeSeparationMetres}};
  for (const ImportedWall& w : walls)
    config["walls"].push_back({{"name", w.name},
                               {"lower_left", vecJson(w.lowerLeft)},
                               {"lower_right", vecJson(w.lowerRight)},
                               {"upper_left", vecJson(w.upperLeft)},
                               {"resolution", json::array({w.width, w.height})}});
  for (std::size_t i = 0; i < walls.size(); ++i) {
    config["walls"][i].update(walls[i].output);
    if (walls[i].preview) config["walls"][i]["preview"] = true;
  }
  DisplayConfig result = parseDisplayConfig(config, sourceName);
  if (report) {
    report->format = display.format;
    report->notes = std::move(display.notes);
  }
  return result;
}

void setImportedNode(ImportedDisplay& display, std::size_t first, const std::string& host) {
  if (host.empty() || host == "localhost" || host == "127.0.0.1" || host == "::1") return;
  for (std::size_t i = first; i < display.walls.size(); ++i) display.walls[i].output["node"] = host;
}

json importedOutput(const ImportedWindow& window) {
  json output = json::object();
  json w = json::object();
  if (window.fullscreen) w["fullscreen"] = window.monitor.value_or(0);
  else if (window.position) w["position"] = {window.position->first, window.position->second};
  if (window.size) w["size"] = {window.size->first, window.size->second};
  if (window.border) w["decorated"] = *window.border;
  if (window.position || window.fullscreen || window.size) output["window"] = w;
  if (window.eye == "left" || window.eye == "right") {
    output["stereo_output"] = window.eye;
  } else if (window.stereo == "none") {
    output["stereo_output"] = "mono";
  } else if (window.stereo == "side_by_side" || window.stereo == "top_bottom") {
    output["stereo_output"] = window.stereo == "side_by_side" ? "side-by-side" : "top-bottom";
  }
  // Other modes (active quad-buffer, anaglyph, ...) have no confvis equivalent: left unset, so
  // `confvis view --eyes` decides.
  return output;
}

// ---- XML -------------------------------------------------------------------------------------

XmlReader::XmlReader(const std::string& text, std::string sourceName)
    : text_(text), sourceName_(std::move(sourceName)) {
  const pugi::xml_parse_result result =
      document_.load_buffer(text_.data(), text_.size(), pugi::parse_default);
  if (!result)
    throw Error(ErrorCode::InvalidInput, sourceName_ + ":" + std::to_string(lineOf(result.offset)) +
                                             ": invalid XML: " + result.description());
}

pugi::xml_node XmlReader::root(const char* rootName) const {
  const pugi::xml_node element = document_.document_element();
  if (!element)
    throw Error(ErrorCode::InvalidInput, sourceName_ + ": no XML element in the file");
  if (std::string(element.name()) != rootName)
    fail(element, std::string("the root element must be <") + rootName + ">");
  return element;
}

int XmlReader::lineOf(std::ptrdiff_t offset) const {
  const auto end = text_.begin() + std::clamp<std::ptrdiff_t>(offset, 0, text_.size());
  return 1 + static_cast<int>(std::count(text_.begin(), end, '\n'));
}

std::string XmlReader::where(const pugi::xml_node& node) const {
  std::string element = "<" + std::string(node.name());
  for (const char* key : {"Name", "name"})
    if (const pugi::xml_attribute a = node.attribute(key))
      element += " " + std::string(key) + "=\"" + a.value() + "\"";
  return sourceName_ + ":" + std::to_string(lineOf(node.offset_debug())) + ": " + element + ">";
}

void XmlReader::fail(const pugi::xml_node& node, const std::string& what) const {
  throw Error(ErrorCode::InvalidInput, where(node) + ": " + what);
}

std::optional<std::string> XmlReader::attribute(const pugi::xml_node& node,
                                                const char* name) const {
  const pugi::xml_attribute a = node.attribute(name);
  if (!a) return std::nullopt;
  return std::string(a.value());
}

double XmlReader::number(const pugi::xml_node& node, const char* name) const {
  const std::optional<std::string> text = attribute(node, name);
  if (!text) fail(node, std::string("attribute '") + name + "' is missing");
  const std::optional<double> value = parseNumber(*text);
  if (!value)
    fail(node, std::string("attribute '") + name + "' must be a finite number, got \"" + *text + "\"");
  return *value;
}

glm::dvec3 XmlReader::xyz(const pugi::xml_node& node) const {
  return {number(node, "x"), number(node, "y"), number(node, "z")};
}

}  // namespace confvis::detail
