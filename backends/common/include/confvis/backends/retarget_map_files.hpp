#pragma once
// Baked retarget maps on disk.
#include <filesystem>

#include <glm/glm.hpp>

#include "confvis/base/export.hpp"
#include "confvis/conformal/retarget_map.hpp"
#include "confvis/engine/display_config.hpp"

namespace confvis CONFVIS_API {

// A directory written by `confvis bake` or writeRetargetMapDirectory (bake_files.hpp), read by
// loadBakeDirectory: verified as a whole (each file's size and checksum in bake.json, float32
// cube maps of the recorded resolution) and with the map's reference point from bake.json.
// Throws Error(FileNotFound) naming a missing directory, Error(InvalidInput) for a directory
// without bake.json, Error(IoFailure) naming the culprit of a corrupt one.
RetargetMap readRetargetMapDirectory(const std::filesystem::path& directory);

}  // namespace confvis
