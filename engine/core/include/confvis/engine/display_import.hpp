#pragma once
// Display descriptions from other CAVE software, so labs reuse the files they have:
//   - SGCT cluster configs, JSON (SGCT 3+) and the older XML (<Cluster>): every viewport with a
//     ProjectionPlane (JSON) or <Viewplane>/<Projectionplane> (XML) becomes a wall. SGCT gives
//     the corners lower-left, upper-left, upper-right in its world frame; the default user's
//     position is the reference point and its eye separation the display's.
//   - ParaView .pvx files: every <Machine> with LowerLeft, LowerRight, UpperRight becomes a
//     wall, Geometry="WxH+X+Y" its resolution, <EyeSeparation Value="..."/> the display's.
//     ParaView has no nominal viewer position: the reference is the room origin unless
//     ImportOptions::reference says otherwise.
// Both formats use the OpenGL frame (+y up, -z forward) that confvis uses; lengths are taken
// as metres times ImportOptions::scale (millimetres are recognised by the display's size). The implied fourth corner is filled in (SGCT:
// lower-right = lower-left + upper-right - upper-left; ParaView: upper-left = lower-left +
// upper-right - lower-right), and the result goes through the same validation as a confvis
// JSON config (rectangles, walls facing the reference, overlaps only as projectors on one plane
// do; a window covering two or more others on their plane is imported as a preview, with a
// note: display_surfaces.hpp), so every error names the
// file and the element (node/window/viewport or machine) at fault.
// Formats and samples: configs/imported/README.md.
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "confvis/base/export.hpp"
#include "confvis/engine/display_config.hpp"

namespace confvis CONFVIS_API {

enum class DisplayFormat { Confvis, SgctJson, SgctXml, ParaViewPvx };

const char* toString(DisplayFormat format) noexcept;

// Thread-safety: a value (options): read it from any number of threads at once.
struct ImportOptions {
  std::string name;                       // display name; empty: the file name without extension
  std::optional<glm::dvec3> reference;    // overrides the file's viewer position (metres)
  // Metres per file unit (0.3048 for a CAVE in feet). Unset: 1, except that a display spanning
  // over 100 file units is read as millimetres (SGCT files often are) and converted, with a note.
  std::optional<double> scale;
  // Windows to leave out, by the wall name the import gives them (before repeated names get
  // "-2"), e.g. a preview window on the master; a name that matches no window is an error.
  std::vector<std::string> skipWindows;
  // Turns on edge blending of overlapping projector walls with this projector gamma
  // (DisplayConfig::edgeBlend); SGCT files carry no blend settings.
  std::optional<double> edgeBlendGamma;
  // Resolution of walls whose file gives none (a .pvx <Machine> without Geometry); without it
  // such a wall is an error naming the machine.
  std::optional<std::pair<int, int>> fallbackResolution;
  // Source field; default: a hemisphere facing the walls when they all lie in one plane (a flat
  // wall), the full sphere otherwise. A forced hemisphere faces the walls' area-weighted mean
  // inward normal.
  std::optional<SourceField> source;
};

// What an import did besides the walls: viewports or machines it skipped and why (a GUI
// window with a planar projection, a second-eye viewport repeating a wall, ...).
struct ImportReport {
  DisplayFormat format = DisplayFormat::Confvis;
  std::vector<std::string> notes;
};

// By extension (.pvx, .xml) and, for .json, by content: an object with "nodes" and without
// "walls" is SGCT's. Error(FileNotFound) if a .json file cannot be read.
DisplayFormat detectDisplayFormat(const std::filesystem::path& path);

// Reads any supported description into a validated DisplayConfig. Error(FileNotFound) naming the
// path, Error(InvalidInput) naming the file and element for malformed content.
DisplayConfig importDisplayConfig(const std::filesystem::path& path,
                                  const ImportOptions& options = {},
                                  ImportReport* report = nullptr);

// The same from text; sourceName (usually the file name) prefixes every error and, when
// options.name is empty, gives the display its name.
DisplayConfig parseSgctJson(const std::string& text, const std::string& sourceName,
                            const ImportOptions& options = {}, ImportReport* report = nullptr);
DisplayConfig parseSgctXml(const std::string& text, const std::string& sourceName,
                           const ImportOptions& options = {}, ImportReport* report = nullptr);
DisplayConfig parseParaViewPvx(const std::string& text, const std::string& sourceName,
                               const ImportOptions& options = {}, ImportReport* report = nullptr);

}  // namespace confvis
