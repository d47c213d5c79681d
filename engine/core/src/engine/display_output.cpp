#include "confvis/engine/display_output.hpp"

#include <cstdint>

#include "confvis/base/error.hpp"

namespace confvis {

using nlohmann::json;

namespace {

// Screen coordinates beyond this are a typo, not a desktop (also keeps w * h in range).
constexpr int kMaxScreenPixels = 65536;

struct StereoName {
  StereoOutput output;
  const char* name;
};
constexpr StereoName kStereoNames[] = {{StereoOutput::Mono, "mono"},
                                       {StereoOutput::SideBySide, "side-by-side"},
                                       {StereoOutput::TopBottom, "top-bottom"},
                                       {StereoOutput::Left, "left"},
                                       {StereoOutput::Right, "right"}};

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  throw Error(ErrorCode::InvalidInput, where + ": " + what);
}

int screenInteger(const json& value, const std::string& where, const char* key) {
  if (!value.is_number_integer())
    fail(where, "'" + std::string(key) + "' must hold integers, got " + value.dump());
  const bool inRange = value.is_number_unsigned()
                           ? value.get<std::uint64_t>() <= static_cast<std::uint64_t>(kMaxScreenPixels)
                           : value.get<std::int64_t>() >= -kMaxScreenPixels &&
                                 value.get<std::int64_t>() <= kMaxScreenPixels;
  if (!inRange)
    fail(where, "'" + std::string(key) + "' is out of range (+-" +
                    std::to_string(kMaxScreenPixels) + " pixels): " + value.dump());
  return value.get<int>();
}

std::pair<int, int> screenPair(const json& window, const std::string& where, const char* key) {
  const json& value = window.at(key);
  if (!value.is_array() || value.size() != 2)
    fail(where, "'" + std::string(key) + "' must be an array of 2 integers, got " + value.dump());
  return {screenInteger(value[0], where, key), screenInteger(value[1], where, key)};
}

MonitorChoice readMonitor(const json& value, const std::string& where) {
  MonitorChoice choice;
  if (value.is_number_integer()) {
    if (value.is_number_unsigned() ? value.get<std::uint64_t>() > 255 : value.get<std::int64_t>() < 0 || value.get<std::int64_t>() > 255)
      fail(where, "'fullscreen' must be a monitor index 0..255 or a monitor name, got " +
                      value.dump());
    choice.index = value.get<int>();
  } else if (value.is_string() && !value.get<std::string>().empty()) {
    choice.name = value.get<std::string>();
  } else {
    fail(where, "'fullscreen' must be a monitor index (0 = primary) or a monitor name, got " +
                    value.dump());
  }
  return choice;
}

WallWindow readWindow(const json& window, const std::string& where) {
  if (!window.is_object()) fail(where, "must be a JSON object, got " + std::string(window.type_name()));
  for (const auto& item : window.items())
    if (item.key() != "position" && item.key() != "size" && item.key() != "fullscreen" &&
        item.key() != "decorated")
      fail(where, "unknown key '" + item.key() + "' (allowed: position, size, fullscreen, decorated)");
  WallWindow result;
  if (window.contains("position")) result.position = screenPair(window, where, "position");
  if (window.contains("size")) {
    result.size = screenPair(window, where, "size");
    if (result.size->first < 1 || result.size->second < 1)
      fail(where, "'size' must be at least 1 x 1 pixels, got " + window.at("size").dump());
  }
  if (window.contains("fullscreen")) {
    result.fullscreen = readMonitor(window.at("fullscreen"), where);
    if (result.position)
      fail(where, "give 'fullscreen' (the monitor's whole screen) or 'position', not both");
  }
  if (window.contains("decorated")) {
    if (!window.at("decorated").is_boolean())
      fail(where, "'decorated' must be true or false, got " + window.at("decorated").dump());
    result.decorated = window.at("decorated").get<bool>();
  }
  return result;
}

}  // namespace

const char* toString(StereoOutput output) noexcept {
  for (const StereoName& entry : kStereoNames)
    if (entry.output == output) return entry.name;
  return "mono";
}

namespace detail {

WallOutput readWallOutput(const json& wallJson, const std::string& where) {
  WallOutput output;
  if (wallJson.contains("window")) output.window = readWindow(wallJson.at("window"), where + " window");
  if (wallJson.contains("stereo_output")) {
    const json& value = wallJson.at("stereo_output");
    std::string list;
    for (const StereoName& entry : kStereoNames) {
      if (value.is_string() && value.get<std::string>() == entry.name) output.stereo = entry.output;
      list += (list.empty() ? "" : ", ") + std::string(entry.name);
    }
    if (!output.stereo)
      fail(where, "'stereo_output' must be one of " + list + ", got " + value.dump());
  }
  return output;
}

void writeWallOutput(const WallOutput& output, json& wallJson) {
  if (output.window) {
    const WallWindow& w = *output.window;
    json window = {{"decorated", w.decorated}};
    if (w.position) window["position"] = {w.position->first, w.position->second};
    if (w.size) window["size"] = {w.size->first, w.size->second};
    if (w.fullscreen)
      window["fullscreen"] = w.fullscreen->name.empty() ? json(w.fullscreen->index)
                                                        : json(w.fullscreen->name);
    wallJson["window"] = window;
  }
  if (output.stereo) wallJson["stereo_output"] = toString(*output.stereo);
}

json withoutWallOutputs(json displayJson) {
  if (displayJson.contains("walls"))
    for (json& wall : displayJson["walls"]) {
      wall.erase("window");
      wall.erase("stereo_output");
      wall.erase("node");  // which cluster process draws it: no map changes either
    }
  return displayJson;
}

}  // namespace detail
}  // namespace confvis
