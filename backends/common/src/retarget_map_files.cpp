#include "confvis/backends/retarget_map_files.hpp"

#include "confvis/base/error.hpp"
#include "confvis/base/file_checks.hpp"
#include "confvis/conformal/bake_files.hpp"

namespace confvis {

RetargetMap readRetargetMapDirectory(const std::filesystem::path& directory) {
  if (!isDirectory(directory))
    throw Error(ErrorCode::FileNotFound,
                "baked map directory '" + directory.string() + "' does not exist");
  // Only a directory verified as a whole is used: bake.json records the reference point the map
  // was baked around and each file's size and checksum (loadBakeDirectory). Two bare EXRs could
  // be swapped, stale or of another display, and would render with exit 0.
  if (!pathExists(directory / "bake.json"))
    throw Error(ErrorCode::InvalidInput,
                "baked map directory '" + directory.string() +
                    "' has no bake.json, so its maps cannot be verified (write it with confvis "
                    "bake -o DIR)");
  return loadBakeDirectory(directory).map;
}

}  // namespace confvis
