#include "shipped_files.hpp"

#include <vector>

#include "confvis/base/error.hpp"

namespace confvis::cli {

namespace fs = std::filesystem;

fs::path shippedFile(const std::string& relative, const std::string& option) {
  std::vector<fs::path> candidates;
  std::error_code error;
  const fs::path exe = fs::read_symlink("/proc/self/exe", error);
  if (!error) {
    candidates.push_back(exe.parent_path() / ".." / relative);
    candidates.push_back(exe.parent_path() / "../share/confvis" / relative);
  }
  candidates.push_back(fs::path(CONFVIS_SOURCE_DIR) / relative);
  for (const fs::path& path : candidates)
    if (fs::exists(path, error)) return fs::weakly_canonical(path);
  throw Error(ErrorCode::FileNotFound,
              "no " + option + " given and the default " + relative +
                  " was not found next to the executable or in " CONFVIS_SOURCE_DIR);
}

}  // namespace confvis::cli
