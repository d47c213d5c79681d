// confvis import: SGCT (JSON, XML) and ParaView .pvx display descriptions to a confvis config.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "command.hpp"
#include "confvis/base/atomic_file.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/file_checks.hpp"
#include "confvis/engine/display_import.hpp"

namespace confvis::cli {
namespace {

struct ImportArgs {
  std::string input, output, name, resolution, source;
  std::vector<double> reference;
  std::vector<std::string> skipWindows;
  std::optional<double> scale, edgeBlend;
};

std::pair<int, int> parseResolution(const std::string& text) {
  int width = 0, height = 0;
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &width, &x, &height, &extra) != 3 || x != 'x' ||
      width <= 0 || height <= 0)
    throw Error(ErrorCode::InvalidInput, "--resolution expects WIDTHxHEIGHT, got '" + text + "'");
  return {width, height};
}

int runImport(const ImportArgs& a) {
  ImportOptions options;
  options.name = a.name;
  options.scale = a.scale;
  options.skipWindows = a.skipWindows;
  options.edgeBlendGamma = a.edgeBlend;
  if (!a.reference.empty()) options.reference = glm::dvec3(a.reference[0], a.reference[1], a.reference[2]);
  if (!a.resolution.empty()) options.fallbackResolution = parseResolution(a.resolution);
  if (a.source == "sphere") options.source = SourceField::FullSphere;
  if (a.source == "hemisphere") options.source = SourceField::Hemisphere;
  std::error_code unreadable;  // as pathExists: an unreadable name is not the input either
  if (!a.output.empty() && pathExists(a.output) &&
      std::filesystem::equivalent(a.input, a.output, unreadable))
    throw Error(ErrorCode::InvalidInput, "-o would overwrite the input '" + a.input + "'");

  ImportReport report;
  const DisplayConfig config = importDisplayConfig(a.input, options, &report);
  for (const std::string& note : report.notes) std::fprintf(stderr, "note: %s\n", note.c_str());
  const std::string text = toJson(config).dump(2) + "\n";
  if (a.output.empty()) {
    std::fputs(text.c_str(), stdout);
  } else {
    writeTextAtomically(a.output, text);
  }
  std::fprintf(stderr, "%s: %s display '%s', %zu walls:", a.input.c_str(), toString(report.format),
               config.name.c_str(), config.walls.size());
  for (const Wall& w : config.walls) std::fprintf(stderr, " %s %dx%d", w.name.c_str(), w.width, w.height);
  std::fprintf(stderr, "; reference (%g, %g, %g)%s%s\n", config.reference.x, config.reference.y,
               config.reference.z, a.output.empty() ? "" : " -> ", a.output.c_str());
  return 0;
}

const RegisterCommand registration{Command{
    "import",
    "Convert an SGCT config (JSON or XML) or a ParaView .pvx file into a confvis display config",
    [](CLI::App& sub) {
      auto args = std::make_shared<ImportArgs>();
      sub.add_option("file", args->input, "SGCT .json/.xml or ParaView .pvx file")
          ->required()
          ->check(CLI::ExistingFile);
      sub.add_option("-o,--output", args->output,
                     "confvis config to write (default: print it on standard output)");
      sub.add_option("--name", args->name, "Display name (default: the input file's name)");
      sub.add_option("--reference", args->reference,
                     "Reference point x,y,z in metres (default: SGCT's user position; ParaView: "
                     "the room origin)")
          ->delimiter(',')
          ->expected(3);
      sub.add_option("--scale", args->scale,
                     "Metres per file unit, e.g. 0.3048 for feet (default: 1, or 0.001 when the "
                     "display spans over 100 units: millimetres, with a note)")
          ->check(kPositiveNumber);
      sub.add_option("--skip-window", args->skipWindows,
                     "Leave out the window (wall) of this name, e.g. a master's preview window; "
                     "repeatable");
      sub.add_option("--edge-blend", args->edgeBlend,
                     "Blend overlapping projector walls, for projectors of this gamma (2.2 "
                     "typical; configs/README.md, \"edge_blend\")")
          ->check(kPositiveNumber);
      sub.add_option("--resolution", args->resolution,
                     "WIDTHxHEIGHT for .pvx machines without Geometry");
      sub.add_option("--source", args->source,
                     "Virtual field shown (default: hemisphere for a flat wall, else sphere)")
          ->check(CLI::IsMember({"sphere", "hemisphere"}));
      return [args] { return runImport(*args); };
    }}};

}  // namespace
}  // namespace confvis::cli
