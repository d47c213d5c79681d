// SGCT cluster configs (JSON and the older XML) to DisplayConfig. SGCT's ProjectionPlane gives
// the screen corners lower-left, upper-left, upper-right in the tracker (world) frame, the frame
// the default user's position is given in; SGCT computes each frustum from the user position and
// those corners (Kooima), exactly what confvis's walls and reference point describe.
// Scene offset/orientation/scale transform the virtual scene, not the screens, and are ignored.
#include <cmath>
#include <string>

#include "confvis/base/error.hpp"
#include "confvis/base/json_text.hpp"
#include "import_parts.hpp"

namespace confvis {

using nlohmann::json;

namespace {

// The implied lower-right corner of SGCT's lower-left / upper-left / upper-right triple.
detail::ImportedWall wallFromSgctCorners(const glm::dvec3& lowerLeft, const glm::dvec3& upperLeft,
                                         const glm::dvec3& upperRight) {
  detail::ImportedWall wall;
  wall.lowerLeft = lowerLeft;
  wall.upperLeft = upperLeft;
  wall.lowerRight = lowerLeft + (upperRight - upperLeft);
  return wall;
}

// A wall's pixels: the window's size times the viewport's fraction of it.
int viewportPixels(int windowPixels, double fraction) {
  return static_cast<int>(std::lround(windowPixels * fraction));
}

std::string wallName(const std::string& viewportName, const std::string& windowName,
                     std::size_t node, std::size_t window, std::size_t viewport,
                     std::size_t viewportsInWindow) {
  if (!viewportName.empty()) return viewportName;
  std::string base = !windowName.empty() ? windowName
                                         : "node" + std::to_string(node) + "-window" +
                                               std::to_string(window);
  if (viewportsInWindow > 1) base += "-viewport" + std::to_string(viewport);
  return base;
}

// ---- JSON ------------------------------------------------------------------------------------

// A JSON value with its path ("nodes[0].windows[1]") for error messages.
class JsonAt {
 public:
  JsonAt(const json& value, std::string path, const std::string& source)
      : value_(value), path_(std::move(path)), source_(source) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw Error(ErrorCode::InvalidInput, source_ + ": " + (path_.empty() ? "" : path_ + ": ") + what);
  }
  const std::string& path() const { return path_; }
  const json& value() const { return value_; }
  bool has(const char* key) const { return value_.is_object() && value_.contains(key); }

  JsonAt at(const char* key) const {
    if (!value_.is_object()) fail("must be a JSON object, got " + std::string(value_.type_name()));
    if (!value_.contains(key)) fail("'" + std::string(key) + "' is required but missing");
    return {value_.at(key), path_.empty() ? key : path_ + "." + key, source_};
  }
  JsonAt at(std::size_t index) const {
    return {value_.at(index), path_ + "[" + std::to_string(index) + "]", source_};
  }

  std::size_t arraySize() const {
    if (!value_.is_array()) fail("must be an array, got " + std::string(value_.type_name()));
    return value_.size();
  }
  std::string string() const {
    if (!value_.is_string()) fail("must be a string, got " + std::string(value_.type_name()));
    return value_.get<std::string>();
  }
  double number() const {
    if (!value_.is_number()) fail("must be a number, got " + std::string(value_.type_name()));
    const double x = value_.get<double>();
    if (!std::isfinite(x)) fail("must be finite");
    return x;
  }
  int integer() const {
    if (!value_.is_number_integer()) fail("must be an integer, got " + value_.dump());
    const auto x = value_.get<std::int64_t>();
    if (x < 0 || x > 1'000'000) fail("is out of range: " + value_.dump());
    return static_cast<int>(x);
  }
  glm::dvec3 xyz() const { return {at("x").number(), at("y").number(), at("z").number()}; }

 private:
  const json& value_;
  std::string path_;
  const std::string& source_;
};

// The window's placement and stereo mode; SGCT JSON: "pos" and "size" {x, y}, "fullscreen",
// "monitor", "border", "stereo", and the viewport's "eye".
detail::ImportedWindow jsonWindow(const JsonAt& window, const JsonAt& viewport) {
  detail::ImportedWindow result;
  auto pair = [](const JsonAt& xy) {
    return std::pair{static_cast<int>(std::lround(xy.at("x").number())),
                     static_cast<int>(std::lround(xy.at("y").number()))};
  };
  auto flag = [](const JsonAt& value) {
    if (!value.value().is_boolean()) value.fail("must be true or false");
    return value.value().get<bool>();
  };
  if (window.has("pos")) result.position = pair(window.at("pos"));
  if (window.has("size")) result.size = pair(window.at("size"));
  if (window.has("fullscreen")) result.fullscreen = flag(window.at("fullscreen"));
  if (window.has("monitor")) result.monitor = window.at("monitor").integer();
  if (window.has("border")) result.border = flag(window.at("border"));
  if (window.has("stereo")) result.stereo = window.at("stereo").string();
  if (viewport.has("eye")) result.eye = viewport.at("eye").string();
  return result;
}

// A window's placement carries over when it shows one wall: confvis opens a window per wall, so
// a window split into several viewports keeps its walls but not its placement.
void carryWindow(detail::ImportedWall& wall, const detail::ImportedWindow& window,
                 std::size_t viewportsInWindow) {
  if (viewportsInWindow == 1) wall.output = detail::importedOutput(window);
}

void readJsonUsers(const JsonAt& root, detail::ImportedDisplay& display) {
  if (!root.has("users")) return;
  const JsonAt users = root.at("users");
  for (std::size_t i = 0; i < users.arraySize(); ++i) {
    const JsonAt user = users.at(i);
    // SGCT's default user is the one without a name; named users serve single viewports.
    if (user.has("name") && !user.at("name").string().empty()) continue;
    if (user.has("pos")) display.viewer = user.at("pos").xyz();
    if (user.has("eyeseparation")) display.eyeSeparation = user.at("eyeseparation").number();
  }
}

void readJsonViewport(const JsonAt& viewport, const JsonAt& window, const std::string& windowName,
                      std::size_t node, std::size_t windowIndex, std::size_t index,
                      std::size_t count, detail::ImportedDisplay& display,
                      const std::string& source) {
  const JsonAt projection = viewport.at("projection");
  const std::string type = projection.at("type").string();
  if (type != "ProjectionPlane") {
    display.notes.push_back(source + ": " + viewport.path() + " uses a " + type +
                            ", not a planar screen; skipped");
    return;
  }
  detail::ImportedWall wall = wallFromSgctCorners(projection.at("lowerleft").xyz(),
                                                  projection.at("upperleft").xyz(),
                                                  projection.at("upperright").xyz());
  const JsonAt size = window.at("size");
  double fx = 1.0, fy = 1.0;
  if (viewport.has("size")) {
    const JsonAt fraction = viewport.at("size");
    fx = fraction.at("x").number();
    fy = fraction.at("y").number();
  }
  wall.width = viewportPixels(size.at("x").integer(), fx);
  wall.height = viewportPixels(size.at("y").integer(), fy);
  wall.element = viewport.path();
  wall.name = wallName("", windowName, node, windowIndex, index, count);
  carryWindow(wall, jsonWindow(window, viewport), count);
  display.walls.push_back(std::move(wall));
}

}  // namespace

DisplayConfig parseSgctJson(const std::string& text, const std::string& sourceName,
                            const ImportOptions& options, ImportReport* report) {
  const json parsed = parseJsonText(text, sourceName);
  const JsonAt root(parsed, "", sourceName);
  detail::ImportedDisplay display;
  display.format = DisplayFormat::SgctJson;
  readJsonUsers(root, display);
  const JsonAt nodes = root.at("nodes");
  for (std::size_t n = 0; n < nodes.arraySize(); ++n) {
    const JsonAt node = nodes.at(n);
    if (!node.has("windows")) continue;
    const std::size_t firstWall = display.walls.size();
    const JsonAt windows = node.at("windows");
    for (std::size_t w = 0; w < windows.arraySize(); ++w) {
      const JsonAt window = windows.at(w);
      const std::string windowName = window.has("name") ? window.at("name").string() : "";
      if (!window.has("viewports")) continue;
      const JsonAt viewports = window.at("viewports");
      const std::size_t count = viewports.arraySize();
      for (std::size_t v = 0; v < count; ++v)
        readJsonViewport(viewports.at(v), window, windowName, n, w, v, count, display,
                         sourceName);
    }
    detail::setImportedNode(display, firstWall,
                            node.has("address") ? node.at("address").string() : "");
  }
  if (display.walls.empty())
    throw Error(ErrorCode::InvalidInput,
                sourceName + ": no viewport with a ProjectionPlane projection, so no walls");
  return detail::finishImport(std::move(display), sourceName, options, report);
}

// ---- XML (SGCT 2 and older) ------------------------------------------------------------------

namespace {

// <Viewplane> (SGCT 1/2) or <Projectionplane> (later XML): three <Pos>, in the order lower-left,
// upper-left, upper-right.
pugi::xml_node planeOf(const pugi::xml_node& viewport) {
  if (pugi::xml_node plane = viewport.child("Viewplane")) return plane;
  return viewport.child("Projectionplane");
}

// SGCT XML: <Window fullScreen= border= monitor=> with <Pos x y/>, <Size x y/>, <Stereo type/>;
// <Viewport eye=>.
detail::ImportedWindow xmlWindow(const detail::XmlReader& xml, const pugi::xml_node& window,
                                 const pugi::xml_node& viewport) {
  detail::ImportedWindow result;
  auto pair = [&](const pugi::xml_node& xy) {
    return std::pair{static_cast<int>(std::lround(xml.number(xy, "x"))),
                     static_cast<int>(std::lround(xml.number(xy, "y")))};
  };
  auto flag = [&](const pugi::xml_node& node, const char* name) -> std::optional<bool> {
    const std::optional<std::string> text = xml.attribute(node, name);
    if (!text) return std::nullopt;
    if (*text != "true" && *text != "false")
      xml.fail(node, std::string("attribute '") + name + "' must be true or false, got \"" +
                         *text + "\"");
    return *text == "true";
  };
  if (const pugi::xml_node pos = window.child("Pos")) result.position = pair(pos);
  if (const pugi::xml_node size = window.child("Size")) result.size = pair(size);
  result.fullscreen = flag(window, "fullScreen").value_or(false);
  result.border = flag(window, "border");
  if (xml.attribute(window, "monitor"))
    result.monitor = static_cast<int>(std::lround(xml.number(window, "monitor")));
  if (const pugi::xml_node stereo = window.child("Stereo"))
    result.stereo = xml.attribute(stereo, "type").value_or("");
  result.eye = xml.attribute(viewport, "eye").value_or("");
  return result;
}

void readXmlViewport(const detail::XmlReader& xml, const pugi::xml_node& viewport,
                     const pugi::xml_node& window, std::size_t node, std::size_t windowIndex,
                     std::size_t index, std::size_t count, detail::ImportedDisplay& display) {
  const pugi::xml_node plane = planeOf(viewport);
  const std::string element = xml.where(viewport);
  if (!plane) {
    display.notes.push_back(element + " has no <Viewplane> or <Projectionplane>, so no planar "
                                      "screen; skipped");
    return;
  }
  std::vector<glm::dvec3> corners;
  for (const pugi::xml_node pos : plane.children("Pos")) corners.push_back(xml.xyz(pos));
  if (corners.size() != 3)
    xml.fail(plane, "needs exactly 3 <Pos> corners (lower-left, upper-left, upper-right), got " +
                        std::to_string(corners.size()));
  detail::ImportedWall wall = wallFromSgctCorners(corners[0], corners[1], corners[2]);
  const pugi::xml_node size = window.child("Size");
  if (!size) xml.fail(window, "has no <Size>, so its viewports have no resolution");
  double fx = 1.0, fy = 1.0;
  if (const pugi::xml_node fraction = viewport.child("Size")) {
    fx = xml.number(fraction, "x");
    fy = xml.number(fraction, "y");
  }
  wall.width = viewportPixels(static_cast<int>(std::lround(xml.number(size, "x"))), fx);
  wall.height = viewportPixels(static_cast<int>(std::lround(xml.number(size, "y"))), fy);
  wall.element = element;
  wall.name = wallName(xml.attribute(viewport, "name").value_or(""),
                       xml.attribute(window, "name").value_or(""), node, windowIndex, index,
                       count);
  carryWindow(wall, xmlWindow(xml, window, viewport), count);
  display.walls.push_back(std::move(wall));
}

}  // namespace

DisplayConfig parseSgctXml(const std::string& text, const std::string& sourceName,
                           const ImportOptions& options, ImportReport* report) {
  const detail::XmlReader xml(text, sourceName);
  const pugi::xml_node cluster = xml.root("Cluster");
  detail::ImportedDisplay display;
  display.format = DisplayFormat::SgctXml;
  for (const pugi::xml_node user : cluster.children("User")) {
    if (!xml.attribute(user, "name").value_or("").empty()) continue;  // default user only
    if (xml.attribute(user, "eyeSeparation")) display.eyeSeparation = xml.number(user, "eyeSeparation");
    if (const pugi::xml_node pos = user.child("Pos")) display.viewer = xml.xyz(pos);
  }
  std::size_t n = 0;
  for (const pugi::xml_node node : cluster.children("Node")) {
    const std::size_t firstWall = display.walls.size();
    std::size_t w = 0;
    for (const pugi::xml_node window : node.children("Window")) {
      const auto viewports = window.children("Viewport");
      const std::size_t count = static_cast<std::size_t>(std::distance(viewports.begin(), viewports.end()));
      std::size_t v = 0;
      for (const pugi::xml_node viewport : viewports)
        readXmlViewport(xml, viewport, window, n, w, v++, count, display);
      ++w;
    }
    detail::setImportedNode(display, firstWall, xml.attribute(node, "address").value_or(""));
    ++n;
  }
  if (display.walls.empty())
    throw Error(ErrorCode::InvalidInput,
                sourceName + ": no <Viewport> with a <Viewplane> or <Projectionplane>, so no walls");
  return detail::finishImport(std::move(display), sourceName, options, report);
}

}  // namespace confvis
