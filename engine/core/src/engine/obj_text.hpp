#pragma once
// OBJ and MTL text prepared for tinyobjloader (private to the OBJ loader). Files from real tools
// trip it up in ways it does not report: UTF-16 reads as no geometry, an unparsable vertex line
// as a vertex at the origin, "usemtl two words" as material "two", "map_Kd .\tex.jpg" (a Windows
// exporter) as a missing file. Here the text is decoded (text_encoding.hpp), vertex lines are
// checked, material names with blanks are protected and backslashes in texture paths become '/'.
#include <filesystem>
#include <string>

namespace confvis::scene_files {

struct ObjText {
  std::string obj;
  std::string mtl;  // every mtllib file the OBJ names, concatenated
};

// Throws Error(InvalidInput) naming the file and line of a vertex line that is not 3 finite
// numbers (v: 3, 4 or 6-7 with colour; vn: 3; vt: 1-3).
ObjText prepareObjText(const std::filesystem::path& path);

// A material name as prepareObjText passes it to tinyobjloader, back as the file spelt it.
std::string restoredMaterialName(const std::string& name);

}  // namespace confvis::scene_files
