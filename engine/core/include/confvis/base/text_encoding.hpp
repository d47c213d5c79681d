#pragma once
// Text files as written by real tools: a UTF-8 byte-order mark, UTF-16 (Windows editors save OBJ
// and MTL files so), CR LF line ends. Readers that expect ASCII/UTF-8 run the bytes through here
// first, so a UTF-16 file is read rather than found to "contain no triangles".
#include <filesystem>
#include <string>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {

// `bytes` as UTF-8 with '\n' line ends: a UTF-8 BOM is dropped, UTF-16 (LE or BE, with a BOM, or
// without one when every other byte of the start is NUL) is transcoded, "\r\n" and lone '\r'
// become '\n'. Throws Error(InvalidInput) naming `path` for malformed UTF-16 and for other
// binary content (NUL bytes) in a file that must be text.
std::string decodeTextFile(const std::string& bytes, const std::filesystem::path& path);

}  // namespace confvis
