#pragma once
// Writes a mesh with per-vertex disk coordinates as OBJ: input vertices in input order, one
// `vt` per vertex, faces as `f v/vt`. Written atomically.
#include <array>
#include <complex>
#include <filesystem>
#include <vector>

#include "confvis/base/export.hpp"
#include "confvis/base/vec3.hpp"

#include "confvis/conformal/mesh.hpp"

namespace confvis CONFVIS_API {
namespace conformal CONFVIS_API {

void writeObjWithDiskCoordinates(const std::filesystem::path& path, const TriMesh& mesh,
                                 const std::vector<std::complex<double>>& uv);

// The same for an indexed triangle list (e.g. a SphereDiskMesh), faces as given.
void writeObjWithDiskCoordinates(const std::filesystem::path& path,
                                 const std::vector<glm::dvec3>& positions,
                                 const std::vector<std::array<int, 3>>& triangles,
                                 const std::vector<std::complex<double>>& uv);

}  // namespace conformal
}  // namespace confvis
