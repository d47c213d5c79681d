#pragma once
// The public headers of the source tree (every .hpp under some include/confvis/), skipping build
// folders (an installed copy) and hidden ones (.git): what the documentation tests scan.
#include <filesystem>
#include <string>
#include <vector>

namespace confvis::test {

inline std::vector<std::filesystem::path> publicHeaders() {
  std::vector<std::filesystem::path> headers;
  const std::filesystem::path root = CONFVIS_SOURCE_DIR;
  for (auto it = std::filesystem::recursive_directory_iterator(root);
       it != std::filesystem::recursive_directory_iterator(); ++it) {
    const std::string name = it->path().filename().string();
    if (it->is_directory() && (name.rfind("build", 0) == 0 || name.rfind('.', 0) == 0)) {
      it.disable_recursion_pending();
      continue;
    }
    if (it->path().extension() == ".hpp" &&
        it->path().generic_string().find("/include/confvis/") != std::string::npos)
      headers.push_back(it->path());
  }
  return headers;
}

}  // namespace confvis::test
