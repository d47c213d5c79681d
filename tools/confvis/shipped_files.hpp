#pragma once
// Files shipped with confvis (configs/, configs/paths/) that commands use as defaults, found
// beside the executable's build or install tree or in the source tree it was built from.
#include <filesystem>
#include <string>

namespace confvis::cli {

// `relative` (e.g. "configs/cave5.json") under the build tree, the install tree's share/confvis
// or the source tree. Throws Error(FileNotFound) naming it and the option that overrides it.
std::filesystem::path shippedFile(const std::string& relative, const std::string& option);

}  // namespace confvis::cli
