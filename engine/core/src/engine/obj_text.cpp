#include "obj_text.hpp"

#include <algorithm>
#include <sstream>
#include <vector>

#include "confvis/base/atomic_file.hpp"
#include "confvis/base/error.hpp"
#include "confvis/base/file_checks.hpp"
#include "confvis/base/text_encoding.hpp"
#include "confvis/engine/number_text.hpp"
#include "scene_file_parts.hpp"

namespace confvis::scene_files {

namespace {

// tinyobjloader takes the whole rest of a newmtl line as the name but only the first word of a
// usemtl line: blanks inside names become this byte on both, and back in restoredMaterialName.
constexpr char kNameBlank = '\x1f';

std::string trimmed(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

// keyword and the rest of the line (trimmed).
std::pair<std::string, std::string> split(const std::string& line) {
  const std::string t = trimmed(line);
  const std::size_t blank = t.find_first_of(" \t");
  if (blank == std::string::npos) return {t, ""};
  return {t.substr(0, blank), trimmed(t.substr(blank))};
}

std::string protectedName(const std::string& name) {
  std::string out = name;
  std::replace(out.begin(), out.end(), ' ', kNameBlank);
  std::replace(out.begin(), out.end(), '\t', kNameBlank);
  return out;
}

bool isTexturePathKeyword(const std::string& keyword) {
  return keyword.rfind("map_", 0) == 0 || keyword == "bump" || keyword == "disp" ||
         keyword == "decal" || keyword == "refl" || keyword == "norm";
}

std::string forwardSlashes(std::string s) {
  std::replace(s.begin(), s.end(), '\\', '/');
  return s;
}

void checkNumbers(const std::string& keyword, const std::string& rest, std::size_t lineNumber,
                  const std::filesystem::path& path) {
  std::istringstream words(rest.substr(0, rest.find('#')));  // a trailing comment is no number
  std::vector<std::string> items;
  for (std::string w; words >> w;) items.push_back(w);
  const std::size_t n = items.size();
  const bool countOk = keyword == "v"    ? (n == 3 || n == 4 || n == 6 || n == 7)
                       : keyword == "vn" ? n == 3
                                         : (n >= 1 && n <= 3);
  bool numbersOk = countOk;
  for (const std::string& item : items) numbersOk = numbersOk && detail::parseNumber(item).has_value();
  if (!numbersOk)
    throw Error(ErrorCode::InvalidInput,
                "OBJ file '" + path.string() + "', line " + std::to_string(lineNumber) +
                    ": cannot read '" + keyword + " " + rest.substr(0, 80) + "' (expected " +
                    (keyword == "v" ? "3 finite numbers" : keyword == "vn" ? "3 finite numbers"
                                                                            : "1 to 3 finite numbers") +
                    ")");
}

std::string prepareMtl(const std::filesystem::path& file) {
  std::istringstream lines(decodeTextFile(readTextFile(file), file));
  std::string out;
  for (std::string line; std::getline(lines, line);) {
    const auto [keyword, rest] = split(line);
    if (keyword == "newmtl") out += "newmtl " + protectedName(rest) + "\n";
    else if (isTexturePathKeyword(keyword)) out += keyword + " " + forwardSlashes(rest) + "\n";
    else out += line + "\n";
  }
  return out;
}

// The files a mtllib line names: the whole rest if that file exists (names with blanks), else
// one per word.
std::vector<std::filesystem::path> mtlFiles(const std::filesystem::path& directory,
                                            const std::string& rest) {
  const std::filesystem::path whole = directory / forwardSlashes(rest);
  if (isRegularFile(whole)) return {whole};
  std::vector<std::filesystem::path> files;
  std::istringstream words(rest);
  for (std::string w; words >> w;) files.push_back(directory / forwardSlashes(w));
  return files;
}

}  // namespace

ObjText prepareObjText(const std::filesystem::path& path) {
  std::istringstream lines(decodeTextFile(readTextFile(path), path));
  ObjText text;
  std::vector<std::filesystem::path> libraries;
  std::size_t lineNumber = 0;
  for (std::string line; std::getline(lines, line);) {
    ++lineNumber;
    const auto [keyword, rest] = split(line);
    if (keyword == "v" || keyword == "vn" || keyword == "vt") {
      checkNumbers(keyword, rest, lineNumber, path);
      text.obj += line + "\n";
    } else if (keyword == "usemtl") {
      text.obj += "usemtl " + protectedName(rest) + "\n";
    } else if (keyword == "mtllib") {
      for (const auto& file : mtlFiles(path.parent_path(), rest))
        if (std::find(libraries.begin(), libraries.end(), file) == libraries.end())
          libraries.push_back(file);
      text.obj += "mtllib materials.mtl\n";  // tinyobjloader reads text.mtl for it
    } else {
      text.obj += line + "\n";
    }
  }
  for (const auto& file : libraries) {
    if (!isRegularFile(file)) {
      warn(path, "material library '" + file.string() + "' not found; materials keep defaults");
      continue;
    }
    text.mtl += prepareMtl(file);
  }
  return text;
}

std::string restoredMaterialName(const std::string& name) {
  std::string out = name;
  std::replace(out.begin(), out.end(), kNameBlank, ' ');
  return out;
}

}  // namespace confvis::scene_files
