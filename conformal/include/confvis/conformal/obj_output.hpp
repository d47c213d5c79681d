#pragma once
// Writes a mesh with per-vertex disk coordinates as OBJ: input vertices in input order, one
// `vt` per vertex, faces as `f v/vt`. Written atomically.
#include <array>
#include <complex>
#include <filesystem>
#include <vector>

#include "confvis/base/vec3.hpp"

#include "confvis/conformal/mesh.hpp"

namespace confvis::conformal {

void writeObjWithDiskCoordinates(const std::filesystem::path& path, const TriMesh& mesh,
                                 const std::vector<std::complex<double>>& uv);

// The same for an indexed triangle list (e.g. a SphereDiskMesh), faces as given.
void writeObjWithDiskCoordinates(const std::filesystem::path& path,
                                 const std::vector<glm::dvec3>& positions,
                                 const std::vector<std::array<int, 3>>& triangles,
                                 const std::vector<std::complex<double>>& uv);

}  // namespace confvis::conformal
