// Format detection and dispatch for display descriptions (display_import.hpp).
#include "confvis/engine/display_import.hpp"

#include <algorithm>
#include <cctype>

#include "confvis/base/atomic_file.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/json_text.hpp"

namespace confvis {

namespace {

std::string lowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// SGCT's JSON has "nodes" (and no confvis "walls"); anything else, including unparsable text,
// is left to the confvis reader, whose errors are the ones a confvis user expects.
bool looksLikeSgctJson(const std::string& text) {
  nlohmann::json parsed;
  try {
    parsed = parseJsonText(text, "");
  } catch (const Error&) {
    return false;
  }
  return parsed.is_object() && parsed.contains("nodes") && !parsed.contains("walls");
}

}  // namespace

const char* toString(DisplayFormat format) noexcept {
  switch (format) {
    case DisplayFormat::Confvis: return "confvis JSON";
    case DisplayFormat::SgctJson: return "SGCT JSON";
    case DisplayFormat::SgctXml: return "SGCT XML";
    case DisplayFormat::ParaViewPvx: return "ParaView .pvx";
  }
  return "unknown";
}

DisplayFormat detectDisplayFormat(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".pvx") return DisplayFormat::ParaViewPvx;
  if (ext == ".xml") return DisplayFormat::SgctXml;
  return looksLikeSgctJson(readTextFile(path)) ? DisplayFormat::SgctJson : DisplayFormat::Confvis;
}

DisplayConfig importDisplayConfig(const std::filesystem::path& path, const ImportOptions& options,
                                  ImportReport* report) {
  const std::string text = readTextFile(path);  // Error(FileNotFound) naming the path
  const std::string source = path.string();
  const std::string ext = lowerExtension(path);
  if (ext == ".pvx") return parseParaViewPvx(text, source, options, report);
  if (ext == ".xml") return parseSgctXml(text, source, options, report);
  if (looksLikeSgctJson(text)) return parseSgctJson(text, source, options, report);
  // A confvis config: the import options still apply, so `confvis import` can rename or move it.
  if (options.scale && *options.scale != 1.0)
    throw Error(ErrorCode::InvalidInput,
                source + ": a confvis config is in metres already; a scale applies to imports only");
  if (!options.skipWindows.empty())
    throw Error(ErrorCode::InvalidInput,
                source + ": a confvis config has walls, not windows; skipping windows applies to "
                         "imports only (remove the wall from the config)");
  if (report) *report = ImportReport{};
  nlohmann::json json = toJson(loadDisplayConfig(path));
  if (!options.name.empty()) json["name"] = options.name;
  if (options.reference)
    json["reference"] = {options.reference->x, options.reference->y, options.reference->z};
  if (options.edgeBlendGamma) json["edge_blend"] = {{"gamma", *options.edgeBlendGamma}};
  if (options.source)
    json["source"]["field"] = *options.source == SourceField::Hemisphere ? "hemisphere" : "sphere";
  return parseDisplayConfig(json, source);
}

}  // namespace confvis
