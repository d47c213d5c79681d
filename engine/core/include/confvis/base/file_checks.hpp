#pragma once
// Whether a path names a file, a directory or anything at all, without throwing. std::filesystem's
// throwing forms fail on a name the file system cannot even look up (longer than NAME_MAX or
// PATH_MAX, a component that is a file): such a name is counted as absent here, so readers report
// it as the missing file it is (one clear FileNotFound naming it) instead of a filesystem_error.
#include <filesystem>

#include "confvis/base/export.hpp"

namespace confvis CONFVIS_API {

bool isRegularFile(const std::filesystem::path& path);  // follows symbolic links
bool isDirectory(const std::filesystem::path& path);    // follows symbolic links
bool pathExists(const std::filesystem::path& path);

}  // namespace confvis
