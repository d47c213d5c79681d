#pragma once
// Baked retarget maps on disk.
#include <filesystem>

#include <glm/glm.hpp>

#include "confvis/conformal/retarget_map.hpp"
#include "confvis/engine/display_config.hpp"

namespace confvis {

// A directory written by `confvis bake` (it has bake.json) is read by loadBakeDirectory, which
// validates it and takes the map's reference point from the sidecar. Otherwise reads DIR/ray.exr
// and DIR/geom.exr (OpenEXR cube maps, confvis layout) with `reference` as the maps' centre. Throws Error(FileNotFound) naming a missing directory or file,
// Error(IoFailure / InvalidInput) naming a malformed one, and Error(InvalidInput) when the two
// maps differ in size.
RetargetMap readRetargetMapDirectory(const std::filesystem::path& directory,
                                     const glm::dvec3& reference);

}  // namespace confvis
