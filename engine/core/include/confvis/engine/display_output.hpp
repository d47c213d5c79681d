#pragma once
// Where a wall's pixels go on a live display (`confvis view`): its window and how a stereo pair
// is laid out in it. Optional per wall; it changes nothing of what is rendered or baked (the
// display's hash leaves it out, so moving a window never invalidates a baked map).
//
// JSON, inside a wall (unknown keys are errors):
//   "window": {
//     "position": [x, y],          optional, screen pixels of the top-left corner
//     "size": [w, h],              optional, screen pixels (>= 1); default: the wall's resolution
//                                  times --scale, shrunk to fit the screen
//     "fullscreen": 0 | "DP-1",    optional, a monitor index or name (not with "position")
//     "decorated": true            optional, title bar and border
//   },
//   "stereo_output": "mono"        optional: mono | side-by-side | top-bottom | left | right
// Without "window" the walls' windows are tiled on the desktop. Without "stereo_output" a
// stereo run shows each wall side by side and a mono run the centre eye. "mono" shows the
// centre eye even in a stereo run; "left" / "right" show that eye alone (one projector of a
// passive-stereo pair, each driven by its own machine or window).
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {

enum class StereoOutput { Mono, SideBySide, TopBottom, Left, Right };

// "mono", "side-by-side", "top-bottom", "left", "right".
const char* toString(StereoOutput output) noexcept;

// A monitor picked by index (glfwGetMonitors order, 0 = primary) or by (part of) its name.
struct MonitorChoice {
  int index = -1;    // >= 0 when chosen by index
  std::string name;  // non-empty when chosen by name
};

struct WallWindow {
  std::optional<std::pair<int, int>> position;  // x, y
  std::optional<std::pair<int, int>> size;      // width, height
  std::optional<MonitorChoice> fullscreen;
  bool decorated = true;
};

// Thread-safety: a value: read it from any number of threads at once; change it from one
// thread while no other reads it.
struct WallOutput {
  std::optional<WallWindow> window;
  std::optional<StereoOutput> stereo;
  bool empty() const { return !window && !stereo; }
};

namespace detail CONFVIS_API {

// Reads "window" and "stereo_output" of one wall's JSON object; `where` ("cave5.json: wall
// 'front'") prefixes every error (Error(InvalidInput)). Absent keys leave the output empty.
WallOutput readWallOutput(const nlohmann::json& wallJson, const std::string& where);

// Adds "window" / "stereo_output" to `wallJson` where set (toJson's canonical form).
void writeWallOutput(const WallOutput& output, nlohmann::json& wallJson);

// The canonical JSON of a display without any wall's output: what the display's hash covers.
nlohmann::json withoutWallOutputs(nlohmann::json displayJson);

}  // namespace detail
}  // namespace confvis
