// ParaView .pvx CAVE descriptions to DisplayConfig. ParaView (vtkDisplayConfiguration::LoadPVX)
// reads, from the <Process Type="server"> element (or the last <Process>, or <pvx> itself since
// ParaView 6.1), <EyeSeparation Value="..."/> (default 0.065) and one <Machine> per display with
// Geometry="WxH+X+Y" and the corners LowerLeft, LowerRight, UpperRight in room coordinates.
// ParaView's older wiki documents UpperLeft instead of UpperRight; both are accepted.
#include <array>
#include <charconv>
#include <string>

#include "confvis/base/error.hpp"
#include "import_parts.hpp"

namespace confvis {

namespace {

// ParaView's default eye separation (vtkDisplayConfiguration), used when the file gives none.
constexpr double kParaViewEyeSeparation = 0.065;

pugi::xml_node serverProcess(const pugi::xml_node& root) {
  pugi::xml_node chosen;
  for (const pugi::xml_node process : root.children("Process")) {
    chosen = process;
    if (std::string(process.attribute("Type").value()) == "server") break;
  }
  return chosen ? chosen : root;
}

// "WxH+X+Y" (X and Y may be negative, "-X"): {W, H, X, Y}, or nullopt when malformed.
std::optional<std::array<int, 4>> parseGeometry(std::string_view text) {
  int values[4] = {0, 0, 0, 0};
  const char* p = text.data();
  const char* end = text.data() + text.size();
  for (int k = 0; k < 4; ++k) {
    if (k == 1) {
      if (p == end || *p != 'x') return std::nullopt;
      ++p;
    } else if (k >= 2) {
      if (p == end || (*p != '+' && *p != '-')) return std::nullopt;
      if (*p == '+') ++p;  // from_chars takes '-' itself but not '+'
    }
    const auto [next, error] = std::from_chars(p, end, values[k]);
    if (error != std::errc() || next == p) return std::nullopt;
    p = next;
  }
  if (p != end) return std::nullopt;
  return std::array{values[0], values[1], values[2], values[3]};
}

void readMachine(const detail::XmlReader& xml, const pugi::xml_node& machine, std::size_t index,
                 const ImportOptions& options, detail::ImportedDisplay& display) {
  const std::optional<std::string> lowerLeft = xml.attribute(machine, "LowerLeft");
  const std::optional<std::string> lowerRight = xml.attribute(machine, "LowerRight");
  const std::optional<std::string> upperRight = xml.attribute(machine, "UpperRight");
  const std::optional<std::string> upperLeft = xml.attribute(machine, "UpperLeft");
  if (!lowerLeft && !lowerRight && !upperRight && !upperLeft) {
    display.notes.push_back(xml.where(machine) + " has no corners (not a CAVE screen); skipped");
    return;
  }
  if (upperRight && upperLeft)
    xml.fail(machine, "give UpperRight (ParaView) or UpperLeft (older form), not both");
  auto corner = [&](const std::optional<std::string>& text, const char* name) {
    if (!text) xml.fail(machine, std::string("attribute '") + name + "' is missing");
    const std::optional<glm::dvec3> v = detail::parseTriple(*text);
    if (!v)
      xml.fail(machine, std::string("attribute '") + name +
                            "' must be three finite numbers \"x y z\", got \"" + *text + "\"");
    return *v;
  };
  detail::ImportedWall wall;
  wall.lowerLeft = corner(lowerLeft, "LowerLeft");
  wall.lowerRight = corner(lowerRight, "LowerRight");
  wall.upperLeft = upperLeft ? corner(upperLeft, "UpperLeft")
                             : wall.lowerLeft + (corner(upperRight, "UpperRight") - wall.lowerRight);
  if (const std::optional<std::string> geometry = xml.attribute(machine, "Geometry")) {
    const auto size = parseGeometry(*geometry);
    if (!size)
      xml.fail(machine, "attribute 'Geometry' must be WIDTHxHEIGHT+X+Y, got \"" + *geometry + "\"");
    wall.width = (*size)[0];
    wall.height = (*size)[1];
    // The X geometry places the machine's window: carry it over for `confvis view`.
    detail::ImportedWindow window;
    window.size = std::pair{(*size)[0], (*size)[1]};
    window.position = std::pair{(*size)[2], (*size)[3]};
    wall.output = detail::importedOutput(window);
  } else if (options.fallbackResolution) {
    std::tie(wall.width, wall.height) = *options.fallbackResolution;
  } else {
    xml.fail(machine, "has no Geometry=\"WIDTHxHEIGHT+X+Y\", so its resolution is unknown; "
                      "give a fallback resolution (confvis import --resolution WxH)");
  }
  wall.name = xml.attribute(machine, "Name").value_or("");
  if (wall.name.empty()) wall.name = "machine" + std::to_string(index);
  wall.element = xml.where(machine);
  display.walls.push_back(std::move(wall));
  // pvserver runs one process per <Machine> on the host it names: so does `--cluster`.
  detail::setImportedNode(display, display.walls.size() - 1, display.walls.back().name);
}

}  // namespace

DisplayConfig parseParaViewPvx(const std::string& text, const std::string& sourceName,
                               const ImportOptions& options, ImportReport* report) {
  const detail::XmlReader xml(text, sourceName);
  const pugi::xml_node process = serverProcess(xml.root("pvx"));
  detail::ImportedDisplay display;
  display.format = DisplayFormat::ParaViewPvx;
  // ParaView's default is metres whatever the file's unit.
  display.eyeSeparationMetres = kParaViewEyeSeparation;
  if (const pugi::xml_node eyes = process.child("EyeSeparation"))
    display.eyeSeparation = xml.number(eyes, "Value");
  std::size_t index = 0;
  for (const pugi::xml_node machine : process.children("Machine"))
    readMachine(xml, machine, index++, options, display);
  if (display.walls.empty())
    throw Error(ErrorCode::InvalidInput,
                xml.where(process) + ": no <Machine> with LowerLeft/LowerRight/UpperRight "
                                     "corners, so no walls");
  return detail::finishImport(std::move(display), sourceName, options, report);
}

}  // namespace confvis
