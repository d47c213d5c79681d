#pragma once
// Baked retarget maps on disk, and the one display that needs no bake.
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

// True when the display's lit walls cover every direction around its reference point (a
// 6-sided CAVE seen from inside): its conformal map is the identity and needs no bake. Checked
// on the texel-centre directions of a cube map of `samplesPerFaceEdge`^2 texels per face.
bool displayCoversWholeSphere(const DisplayConfig& config, int samplesPerFaceEdge = 32);

}  // namespace confvis
