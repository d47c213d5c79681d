#pragma once
// Shared by the SGCT and ParaView importers (private to confvis_engine): the walls an importer
// found, in file units, and the step that turns them into a validated DisplayConfig.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <pugixml.hpp>

#include "confvis/engine/display_import.hpp"
#include "confvis/engine/number_text.hpp"

namespace confvis::detail {

struct ImportedWall {
  std::string name;     // may repeat; finishImport makes names unique
  std::string element;  // where it came from, for notes: "node 0 window 1 viewport 0"
  glm::dvec3 lowerLeft{0.0}, lowerRight{0.0}, upperLeft{0.0};  // file units
  int width = 0, height = 0;
  bool preview = false;  // covers other walls on their plane (set by finishImport)
  // "window" / "stereo_output" for the wall's JSON (display_output.hpp), where the file says.
  nlohmann::json output = nlohmann::json::object();
};

// A window as SGCT (JSON and XML) and ParaView describe it, in screen pixels.
struct ImportedWindow {
  std::optional<std::pair<int, int>> position, size;
  bool fullscreen = false;
  std::optional<int> monitor;
  std::optional<bool> border;
  std::string stereo;  // SGCT's stereo mode ("none", "side_by_side", ...); empty: not given
  std::string eye;     // SGCT viewport eye ("left", "right", "center"); empty: not given
};

// The wall's output JSON for `window`. Stereo modes confvis has no equivalent for (SGCT's active
// quad-buffer, anaglyph, ...) are left unset, so `confvis view --eyes` decides.
nlohmann::json importedOutput(const ImportedWindow& window);

struct ImportedDisplay {
  DisplayFormat format = DisplayFormat::Confvis;
  std::vector<ImportedWall> walls;
  std::optional<glm::dvec3> viewer;        // file units
  std::optional<double> eyeSeparation;     // file units
  std::optional<double> eyeSeparationMetres;  // a format's default, in metres whatever the unit
  std::vector<std::string> notes;
};

// The host (SGCT node address, ParaView machine name) that draws display.walls[first..]: their
// "node" for cluster runs. Loopback names ("localhost", "127.0.0.1", "::1") and empty ones name
// no host (a one-machine setup: any rank may draw the wall).
void setImportedNode(ImportedDisplay& display, std::size_t first, const std::string& host);

// Scales, names, drops walls that repeat an earlier wall's corners (a second stereo eye), picks
// the source field, then validates through parseDisplayConfig so geometric errors read exactly
// like those of a confvis config ("FILE: wall 'NAME': ...").
DisplayConfig finishImport(ImportedDisplay display, const std::string& sourceName,
                           const ImportOptions& options, ImportReport* report);

// An XML file parsed with pugixml; Error(InvalidInput) "SOURCE:LINE: invalid XML: WHAT" when it
// is not well-formed. Messages about elements carry the file and line of the element.
class XmlReader {
 public:
  XmlReader(const std::string& text, std::string sourceName);

  // The document element, which must be named `rootName` (else an error naming what was found).
  pugi::xml_node root(const char* rootName) const;
  // "SOURCE:LINE: <Element Name="x">" for messages about `node`.
  std::string where(const pugi::xml_node& node) const;
  [[noreturn]] void fail(const pugi::xml_node& node, const std::string& what) const;
  // Attribute helpers; each failure names the element and the attribute.
  std::optional<std::string> attribute(const pugi::xml_node& node, const char* name) const;
  double number(const pugi::xml_node& node, const char* name) const;
  glm::dvec3 xyz(const pugi::xml_node& node) const;  // attributes x, y, z

 private:
  int lineOf(std::ptrdiff_t offset) const;

  std::string text_;
  std::string sourceName_;
  pugi::xml_document document_;
};

}  // namespace confvis::detail
