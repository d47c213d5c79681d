#pragma once
// Files are written atomically: to a temporary beside the destination, then renamed over it,
// so a crash or a full disk never leaves a half-written map, image or report behind.
#include <filesystem>
#include <functional>
#include <string>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {

// Calls write(tempPath), then renames tempPath to path. On any failure the temporary is removed
// and an Error(IoFailure) naming `path` is thrown. Creates missing parent directories.
void writeFileAtomically(const std::filesystem::path& path,
                         const std::function<void(const std::filesystem::path& tempPath)>& write);

// Convenience for text and binary blobs.
void writeTextAtomically(const std::filesystem::path& path, const std::string& contents);

// Reads a whole file; throws Error(FileNotFound) naming the path when it cannot be opened.
std::string readTextFile(const std::filesystem::path& path);

}  // namespace confvis
