#include "confvis/base/file_checks.hpp"

#include <system_error>

namespace confvis {

// The error_code forms: an unreadable name leaves the error set and answers false.
bool isRegularFile(const std::filesystem::path& path) {
  std::error_code unreadable;
  return std::filesystem::is_regular_file(path, unreadable);
}

bool isDirectory(const std::filesystem::path& path) {
  std::error_code unreadable;
  return std::filesystem::is_directory(path, unreadable);
}

bool pathExists(const std::filesystem::path& path) {
  std::error_code unreadable;
  return std::filesystem::exists(path, unreadable);
}

}  // namespace confvis
