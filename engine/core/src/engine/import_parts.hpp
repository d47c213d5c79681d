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
};

struct ImportedDisplay {
  DisplayFormat format = DisplayFormat::Confvis;
  std::vector<ImportedWall> walls;
  std::optional<glm::dvec3> viewer;        // file units
  std::optional<double> eyeSeparation;     // file units
  std::vector<std::string> notes;
};

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
